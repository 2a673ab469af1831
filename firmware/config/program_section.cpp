// The G-code interpreter's sections of the configuration:
//
//   [tools]              1 = "mild-3mm"     (a tool number selects a material)
//   [materials.mild-3mm] feed = 2500 (mm/min), pierce_delay = 0.4 (s)
//   [mcodes.M101]        action = "on" | "off" | "dwell" | "ignore", output = 3, seconds = 0.5
//   [outputs]            torch = 0, mist = 1, flood = 2   (M62..M65 P numbers)
//   [analog]             ignore = [0, 1]   (M67/M68 E and M66 E numbers kerf run ignores)
//   [sim]                operator_delay = 1.0 (s), start = [x, y] (mm)
#include <cstdlib>
#include <string>

#include "config/sections.hpp"

namespace kerf::config {

namespace {

void read_materials(TableReader& root, std::map<std::string, job::Material>& out) {
  const toml::table* t = root.table("materials");
  if (!t) return;
  for (const auto& [key, node] : *t) {
    const std::string name(key.str());
    const std::string path = "materials." + name;
    const toml::table* m = node.as_table();
    if (!m) {
      root.problems().add(line_of(node, 1), path, std::string("expected a table, got ") + type_phrase(node));
      continue;
    }
    TableReader r(*m, path, line_of(node, 1), root.problems());
    job::Material mat;
    mat.name = name;
    r.positive("feed", mat.feed_mm_min);
    r.non_negative("pierce_delay", mat.pierce_delay_s);
    r.finish();
    out[name] = mat;
  }
}

void read_tools(TableReader& root, const std::map<std::string, job::Material>& materials, Program& p) {
  const toml::table* t = root.table("tools");
  if (!t) return;
  TableReader r(*t, "tools", line_of(*t, 1), root.problems());
  for (const auto& [key, node] : *t) {
    const std::string k(key.str());
    r.known(k);
    char* end = nullptr;
    const long n = std::strtol(k.c_str(), &end, 10);
    if (k.empty() || *end != '\0' || n < 0 || n > 99999) {
      r.problem(k, "expected a tool number (0..99999) as the key");
      continue;
    }
    std::string name;
    if (!r.string(k, name)) continue;
    const auto m = materials.find(name);
    if (m == materials.end()) {
      r.problem(k, "no [materials." + name + "] section");
      continue;
    }
    p.tool_material[static_cast<int>(n)] = m->second;
  }
}

void read_mcodes(TableReader& root, Program& p) {
  const toml::table* t = root.table("mcodes");
  if (!t) return;
  for (const auto& [key, node] : *t) {
    const std::string k(key.str());
    const std::string path = "mcodes." + k;
    char* end = nullptr;
    const long n = k.size() > 1 && (k[0] == 'M' || k[0] == 'm') ? std::strtol(k.c_str() + 1, &end, 10) : -1;
    if (n < 100 || n > 199 || *end != '\0') {
      root.problems().add(line_of(node, 1), path, "expected a user M-code M100..M199 as the key");
      continue;
    }
    const toml::table* m = node.as_table();
    if (!m) {
      root.problems().add(line_of(node, 1), path, std::string("expected a table, got ") + type_phrase(node));
      continue;
    }
    TableReader r(*m, path, line_of(node, 1), root.problems());
    job::UserMcode u;
    std::string action;
    if (!r.string("action", action) && !r.has("action")) r.problem("action", "missing (on, off, dwell or ignore)");
    if (action == "on") u.action = job::UserMcode::Action::on;
    else if (action == "off") u.action = job::UserMcode::Action::off;
    else if (action == "dwell") u.action = job::UserMcode::Action::dwell;
    else if (action == "ignore") u.action = job::UserMcode::Action::ignore;
    else if (!action.empty()) r.problem("action", "expected on, off, dwell or ignore, got " + quote(action));
    const bool out = u.action == job::UserMcode::Action::on || u.action == job::UserMcode::Action::off;
    if (r.integer("output", u.output, 0, 255) && !out) r.problem("output", "only with action = \"on\" or \"off\"");
    if (out && !r.has("output")) r.problem("output", "missing (the output number)");
    const bool dwell = u.action == job::UserMcode::Action::dwell;
    if (r.non_negative("seconds", u.seconds) && !dwell) r.problem("seconds", "only with action = \"dwell\"");
    if (dwell && !r.has("seconds")) r.problem("seconds", "missing (the dwell in s)");
    r.finish();
    p.mcodes[static_cast<int>(n)] = u;
  }
}

// [analog] ignore = [0, 1]: kerf has no analog lines; these analog numbers
// (M67/M68 E outputs, M66 E inputs) are accepted by kerf run and ignored.
void read_analog(TableReader& root, Program& p) {
  const toml::table* t = root.table("analog");
  if (!t) return;
  TableReader r(*t, "analog", line_of(*t, 1), root.problems());
  if (const toml::array* a = r.array("ignore", "an array of analog numbers, e.g. [0, 1]")) {
    for (const toml::node& n : *a) {
      const auto* k = n.as_integer();
      if (k == nullptr || k->get() < 0 || k->get() > 255) {
        r.problem("ignore", "expected analog numbers 0..255, got " +
                                (k != nullptr ? std::to_string(k->get()) : std::string(type_phrase(n))));
        break;
      }
      p.analog_ignore.push_back(static_cast<int>(k->get()));
    }
  }
  r.finish();
}

}  // namespace

void read_program(TableReader& root, Program& p, Sim& sim) {
  std::map<std::string, job::Material> materials;
  read_materials(root, materials);
  read_tools(root, materials, p);
  read_mcodes(root, p);
  read_analog(root, p);
  if (const toml::table* t = root.table("outputs")) {
    TableReader r(*t, "outputs", line_of(*t, 1), root.problems());
    r.integer("torch", p.torch_output, 0, 255);
    r.integer("mist", p.mist_output, 0, 255);
    r.integer("flood", p.flood_output, 0, 255);
    r.finish();
  }
  if (const toml::table* t = root.table("sim")) {
    TableReader r(*t, "sim", line_of(*t, 1), root.problems());
    r.non_negative("operator_delay", sim.operator_delay);
    if (const toml::array* a = r.array("start", "an array of two numbers [x, y]")) {
      // Each of the two: a TOML float or integer.
      auto value = [&](std::size_t i, double& v) {
        const toml::node* n = a->size() == 2 ? a->get(i) : nullptr;
        if (n == nullptr) return false;
        if (const auto* f = n->as_floating_point()) return v = f->get(), true;
        if (const auto* k = n->as_integer()) return v = static_cast<double>(k->get()), true;
        return false;
      };
      double x = 0, y = 0;
      if (value(0, x) && value(1, y)) {
        sim.start[0] = x;
        sim.start[1] = y;
      } else {
        r.problem("start", "expected two numbers [x, y] (mm)");
      }
    }
    r.finish();
  }
}

job::InterpSettings interp_settings(const Config& c, bool strict) {
  job::InterpSettings s;
  s.fit_tol = c.fit.tol;
  s.cut_feed = c.cut.feed;
  s.tool_material = c.program.tool_material;
  s.mcodes = c.program.mcodes;
  s.strict_mcodes = strict;
  s.torch_output = c.program.torch_output;
  s.mist_output = c.program.mist_output;
  s.flood_output = c.program.flood_output;
  s.start[0] = c.sim.start[0];
  s.start[1] = c.sim.start[1];
  s.z_axis = c.machine.axes.size() > 2;  // [[machine.axis]] name = "z": Z runs as moves
  return s;
}

}  // namespace kerf::config
