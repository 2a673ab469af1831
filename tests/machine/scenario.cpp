#include "scenario.hpp"

#include "config/tomlpp.hpp"

namespace kerf::test {

namespace {

std::string dir_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

std::string where(const std::string& file, const toml::node* n) {
  return file + ":" + std::to_string(n ? n->source().begin.line : 0) + ": ";
}

}  // namespace

bool load_scenario(const std::string& path, const std::string& examples_dir, Scenario& out, std::string& error) {
  toml::parse_result parsed = toml::parse_file(path);
  if (!parsed) {
    error = path + ":" + std::to_string(parsed.error().source().begin.line) + ": " +
            std::string(parsed.error().description());
    return false;
  }
  const toml::table& t = parsed.table();
  out = Scenario{};
  out.file = path;
  const std::string dir = dir_of(path);
  for (const auto& [key, node] : t) {
    const std::string k(key.str());
    if (k == "description" && node.is_string()) out.description = *node.value<std::string>();
    else if (k == "job" && node.is_string()) out.job = dir + "/" + *node.value<std::string>();
    else if (k == "config" && node.is_string()) out.config = dir + "/" + *node.value<std::string>();
    else if (k == "tol" && node.is_number()) out.tol = *node.value<double>();
    else if (k == "gpio" && node.is_string()) out.gpio_script = *node.value<std::string>();
    else if (k == "faults" && node.is_array()) {
      for (const auto& f : *node.as_array()) {
        if (!f.is_string()) {
          error = where(path, &f) + "faults: expected strings";
          return false;
        }
        out.faults.push_back(*f.value<std::string>());
      }
    } else if (k == "expect" && node.is_table()) {
      for (const auto& [ekey, e] : *node.as_table()) {
        const std::string ek(ekey.str());
        Scenario::Expect& x = out.expect;
        if (ek == "state" && e.is_string()) x.state = *e.value<std::string>();
        else if (ek == "reason" && e.is_string()) x.reason = *e.value<std::string>();
        else if (ek == "torch" && e.is_string()) x.torch = *e.value<std::string>();
        else if (ek == "paths_completed" && e.is_integer()) x.paths_completed = *e.value<long>();
        else if (ek == "pierces" && e.is_integer()) x.pierces = *e.value<long>();
        else if (ek == "safe_stop_at" && e.is_number()) x.safe_stop_at = *e.value<double>();
        else if (ek == "torch_off_by" && e.is_number()) x.torch_off_by = *e.value<double>();
        else if (ek == "resume" && e.is_boolean()) x.resume = *e.value<bool>();
        else {
          error = where(path, &e) + "expect." + ek + ": unknown key or wrong type";
          return false;
        }
      }
    } else {
      error = where(path, &node) + k + ": unknown key or wrong type";
      return false;
    }
  }
  if (out.job.empty() || out.expect.state.empty()) {
    error = path + ": a scenario needs job and expect.state";
    return false;
  }
  if (out.config.empty()) out.config = examples_dir + "/sim.toml";
  return true;
}

}  // namespace kerf::test
