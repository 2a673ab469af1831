#include "config/sections.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <string_view>

namespace kerf::config {

namespace {

constexpr double kMaxPeriod = 0.1;  // s: slower than 10 Hz is no servo loop

std::string index_path(const std::string& base, std::size_t i) {
  return base + "[" + std::to_string(i) + "]";
}

void read_axes(TableReader& r, Machine& m) {
  const toml::array* axes = r.array("axis", "an array of tables ([[machine.axis]])");
  if (!axes) return;
  static constexpr std::array<const char*, 3> kNames = {"x", "y", "z"};
  if (axes->size() < 2 || axes->size() > kNames.size()) {
    r.problem("axis", "need 2 or 3 axes (x, y, then optionally z), got " +
                          std::to_string(axes->size()));
    return;
  }
  std::vector<Axis> out;
  for (std::size_t i = 0; i < axes->size(); ++i) {
    const toml::node& node = *axes->get(i);
    const std::string path = index_path(r.key_path("axis"), i);
    const std::uint32_t line = line_of(node, r.line("axis"));
    const toml::table* t = node.as_table();
    if (!t) {
      r.problems().add(line, path, std::string("expected a table, got ") + type_phrase(node));
      continue;
    }
    TableReader a(*t, path, line, r.problems());
    Axis axis;
    if (a.string("name", axis.name) && axis.name != kNames[i])
      a.problem("name", std::string("expected \"") + kNames[i] +
                            "\" (axes are x, y, then optionally z), got " + quote(axis.name));
    if (!a.has("name")) a.problem("name", "missing (x, y or z)");
    a.positive("counts_per_mm", axis.counts_per_mm);
    // No default here: a wrong scale would cut a wrongly sized part.
    if (!a.has("counts_per_mm")) a.problem("counts_per_mm", "missing (drive counts per mm)");
    if (i == 2) axis.home_dir = 1;  // a torch homes up, clear of the sheet
    a.integer("home_dir", axis.home_dir, -1, 1);
    if (axis.home_dir == 0) a.problem("home_dir", "expected -1 or 1 (the side the switch is on), got 0");
    a.positive("home_search_speed", axis.home_search_speed);
    a.positive("home_latch_speed", axis.home_latch_speed);
    a.positive("home_search_distance", axis.home_search_distance);
    a.non_negative("home_backoff", axis.home_backoff);
    a.number("home_position", axis.home_position);
    a.integer("home_input", axis.home_input, 0, 255);
    if (i == 2 && a.has("home_input"))  // kerf's GPIO search jogs in XY
      a.problem("home_input", "a GPIO home switch homes x or y; z homes on the board's or drive's own input");
    if (i == 2) {  // z's own limits
      a.positive("feed", axis.feed);
      a.positive("accel", axis.accel);
    }
    if (i < 2) {  // x's and y's soft limits
      axis.has_min = a.number("min", axis.min);
      axis.has_max = a.number("max", axis.max);
      if (axis.has_min && axis.has_max && !(axis.min < axis.max))
        a.problem("max", "must be > min (" + format_number(axis.min) + "), got " + format_number(axis.max));
    }
    a.finish();
    out.push_back(axis);
  }
  m.axes = out;
}

}  // namespace

void read_machine(TableReader& r, Machine& m) {
  read_axes(r, m);
  r.positive("max_feed", m.max_feed);
  // Rapids default to the machine's top speed, whatever that is.
  if (!r.positive("rapid_feed", m.rapid_feed) && !r.has("rapid_feed")) m.rapid_feed = m.max_feed;
  r.positive("accel", m.accel);
  r.non_negative("jerk", m.jerk);
  r.positive_at_most("servo_period", m.servo_period, kMaxPeriod);
  r.positive_at_most("cycle", m.cycle, kMaxPeriod);
  r.string("state", m.state);
  r.positive("ferror", m.ferror);
  r.positive("min_ferror", m.min_ferror);
  r.boolean("home_switches", m.home_switches);
  r.positive("jog_speed", m.jog_speed);
  r.finish();
}

void check_machine(TableReader& machine, const Machine& m) {
  if (m.rapid_feed > m.max_feed)
    machine.problem("rapid_feed", "must be <= machine.max_feed (" + format_number(m.max_feed) +
                                      "), got " + format_number(m.rapid_feed));
  if (m.min_ferror > m.ferror)
    machine.problem(machine.has("min_ferror") ? "min_ferror" : "ferror",
                    "machine.min_ferror (" + format_number(m.min_ferror) + ") must be <= machine.ferror (" +
                        format_number(m.ferror) + ")");
}

// ---- link -------------------------------------------------------------------

namespace {

struct KindName {
  Link::Kind kind;
  const char* name;
};
constexpr std::array<KindName, 3> kKinds = {{
    {Link::Kind::modbus_tcp, "modbus-tcp"},
    {Link::Kind::modbus_rtu, "modbus-rtu"},
    {Link::Kind::can, "can"},
}};

// Which link kinds use a key; a key of another kind is refused, as a typo would be.
struct KeyUse {
  const char* key;
  bool tcp, rtu, can;
};
constexpr std::array<KeyUse, 9> kLinkKeys = {{
    {"host", true, false, false},
    {"port", true, false, false},
    {"device", false, true, false},
    {"baud", false, true, false},
    {"unit", true, true, false},
    {"iface", false, false, true},
    {"node_ids", false, false, true},
    {"sync_ms", false, false, true},
    {"timeout", true, true, true},
}};

bool used_by(const KeyUse& k, Link::Kind kind) {
  switch (kind) {
    case Link::Kind::modbus_tcp: return k.tcp;
    case Link::Kind::modbus_rtu: return k.rtu;
    case Link::Kind::can: return k.can;
  }
  return false;
}

void read_node_ids(TableReader& r, Link& link) {
  const toml::array* ids = r.array("node_ids", "an array of integers");
  if (!ids) return;
  std::vector<int> out;
  for (std::size_t i = 0; i < ids->size(); ++i) {
    const toml::node& node = *ids->get(i);
    const std::string path = index_path(r.key_path("node_ids"), i);
    const std::uint32_t line = line_of(node, r.line("node_ids"));
    const auto* v = node.as_integer();
    if (!v) {
      r.problems().add(line, path, std::string("expected an integer, got ") + type_phrase(node));
      continue;
    }
    if (v->get() < 1 || v->get() > 127) {
      r.problems().add(line, path, "must be in 1..127, got " + std::to_string(v->get()));
      continue;
    }
    const int id = static_cast<int>(v->get());
    const auto dup = std::find(out.begin(), out.end(), id);
    if (dup != out.end()) {
      r.problems().add(line, path,
                       "node " + std::to_string(id) + " is already " +
                           index_path(r.key_path("node_ids"),
                                      static_cast<std::size_t>(dup - out.begin())));
      continue;
    }
    out.push_back(id);
  }
  link.node_ids = out;
}

}  // namespace

void read_link(TableReader& r, Link& link) {
  std::string kind;
  bool kind_known = false;
  if (r.string("kind", kind)) {
    for (const auto& k : kKinds)
      if (kind == k.name) {
        link.kind = k.kind;
        kind_known = true;
      }
    if (!kind_known)
      r.problem("kind", "unknown link " + quote(kind) + " (expected modbus-tcp, modbus-rtu or can)");
  } else if (!r.has("kind")) {
    r.problem("kind", "missing (expected modbus-tcp, modbus-rtu or can)");
  }
  for (const auto& k : kLinkKeys) {
    if (!r.has(k.key) || !kind_known) {
      r.known(k.key);  // unknown kind: one message is enough
      continue;
    }
    if (!used_by(k, link.kind)) {
      r.known(k.key);
      r.problem(k.key, std::string("not used by a ") + to_string(link.kind) + " link");
    }
  }
  if (kind_known) {
    switch (link.kind) {
      case Link::Kind::modbus_tcp:
        r.string("host", link.host);
        r.integer("port", link.port, 1, 65535);
        r.integer("unit", link.unit, 1, 247);
        break;
      case Link::Kind::modbus_rtu:
        r.string("device", link.device);
        r.integer("baud", link.baud, 1, 4000000);
        r.integer("unit", link.unit, 1, 247);
        break;
      case Link::Kind::can:
        r.string("iface", link.iface);
        read_node_ids(r, link);
        r.number_in("sync_ms", link.sync_ms, 1, 10);
        break;
    }
  }
  r.positive("timeout", link.timeout);
  r.finish();
}

void check_link(TableReader& link_reader, const Link& link, const TableReader& machine,
                const Machine& m) {
  // A key that is missing is reported at the kind that needs it.
  const auto missing = [&](const char* key, const std::string& reason) {
    link_reader.problems().add(link_reader.line("kind"), link_reader.key_path(key), reason);
  };
  if (link.kind == Link::Kind::modbus_rtu && !link_reader.has("device"))
    missing("device", "required for a modbus-rtu link (e.g. \"/dev/ttyUSB0\")");
  if (link.kind != Link::Kind::can) return;
  if (!link_reader.has("node_ids")) {
    missing("node_ids", "required for a can link: one node id per axis (" +
                                        std::to_string(m.axes.size()) + " axes)");
  } else if (link.node_ids.size() != m.axes.size()) {
    link_reader.problem("node_ids", "need one node id per axis (" + std::to_string(m.axes.size()) +
                                        " axes" + (machine.has("axis") ? "" : ", the default x and y") +
                                        "), got " + std::to_string(link.node_ids.size()));
  }
}

const char* to_string(Link::Kind k) {
  for (const auto& kind : kKinds)
    if (kind.kind == k) return kind.name;
  return "?";
}

// ---- fit, cut, rt -----------------------------------------------------------

namespace {

// A value named by a string: `parse` gives it, or nothing for a name it does
// not know (the problem "unknown <what> "NAME" (expected <names>)").
template <class T>
void read_name(TableReader& r, const char* key, std::optional<T> (*parse)(std::string_view), T& out,
               const char* what, const char* names) {
  std::string text;
  if (!r.string(key, text)) return;
  if (const std::optional<T> v = parse(text))
    out = *v;
  else
    r.problem(key, std::string("unknown ") + what + " " + quote(text) + " (expected " + names + ")");
}

}  // namespace

void read_fit(TableReader& r, Fit& fit) {
  read_name(r, "criterion", job::parse_criterion, fit.criterion, "criterion", "vertex, band or biarc");
  read_name(r, "numeric", job::parse_numeric, fit.numeric, "type", "double or fixed");
  r.positive("tol", fit.tol);
  r.finish();
}

void read_cut(TableReader& r, Cut& cut) {
  r.positive("feed", cut.feed);
  r.non_negative("pierce_delay", cut.pierce_delay);
  r.positive("arc_ok_timeout", cut.arc_ok_timeout);
  read_cut_rules(r, cut.rules);
  r.finish();
}

void check_cut(TableReader& cut_reader, const Cut& cut, TableReader& machine, const Machine& m) {
  if (cut.feed <= m.max_feed) return;
  const std::string reason = "must be <= machine.max_feed (" + format_number(m.max_feed) +
                             "), got " + format_number(cut.feed);
  if (cut_reader.has("feed"))
    cut_reader.problem("feed", reason);
  else  // the default feed is too fast for this machine: point at the machine's limit
    machine.problems().add(machine.line("max_feed"), "cut.feed",
                           reason + " (the default; set cut.feed)");
}

void read_rt(TableReader& r, Rt& rt) {
  r.integer("priority", rt.priority, 0, 99);
  r.boolean("lock_memory", rt.lock_memory);
  r.finish();
}

void read_bench(TableReader& r, Bench& bench) {
  r.boolean("enabled", bench.enabled);
  r.finish();
}

}  // namespace kerf::config
