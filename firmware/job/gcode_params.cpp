#include "job/gcode_params.hpp"

#include <cstdio>

namespace kerf::job {

namespace {
bool is_global(const std::string& name) { return !name.empty() && name[0] == '_'; }
}  // namespace

bool GcodeParams::read(int n, double& v, std::string& reason) const {
  if (n < 1 || n > kMaxNumbered) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "#%d: %s", n,
                  n >= 5000 && n <= 5602 ? "system parameters (probe, offsets, position) are not supported"
                                         : "no such parameter (#1..#4999)");
    reason = buf;
    return false;
  }
  v = numbered_[static_cast<std::size_t>(n)];
  return true;
}

bool GcodeParams::write(int n, double v, std::string& reason) {
  double dummy = 0;
  if (!read(n, dummy, reason)) return false;
  numbered_[static_cast<std::size_t>(n)] = v;
  return true;
}

bool GcodeParams::read(const std::string& name, double& v, std::string& reason) const {
  if (name.rfind("_hal[", 0) == 0 && name.size() > 6 && name.back() == ']')
    return hal_(std::string_view(name).substr(5, name.size() - 6), v, reason);
  const std::map<std::string, double>& m = is_global(name) ? globals_ : frames_.back().locals;
  const auto it = m.find(name);
  if (it == m.end()) {
    reason = "#<";
    reason += name;
    reason += "> is read before it is set";
    return false;
  }
  v = it->second;
  return true;
}

void GcodeParams::write(const std::string& name, double v) {
  (is_global(name) ? globals_ : frames_.back().locals)[name] = v;
}

bool GcodeParams::exists(const std::string& name) const {
  const std::map<std::string, double>& m = is_global(name) ? globals_ : frames_.back().locals;
  return m.count(name) != 0;
}

bool GcodeParams::push_call(const std::vector<double>& args, std::string& reason) {
  if (frames_.size() > kMaxCallDepth) {
    reason = "subroutine calls nested deeper than " + std::to_string(kMaxCallDepth);
    return false;
  }
  if (args.size() > kArgs) {
    reason = "a call takes at most 30 arguments";
    return false;
  }
  Frame f;
  for (int k = 0; k < kArgs; ++k) {
    const auto i = static_cast<std::size_t>(k);
    f.args[i] = numbered_[i + 1];
    numbered_[i + 1] = i < args.size() ? args[i] : 0.0;
  }
  frames_.push_back(std::move(f));
  return true;
}

void GcodeParams::pop_call() {
  if (frames_.size() <= 1) return;
  for (std::size_t i = 0; i < kArgs; ++i) numbered_[i + 1] = frames_.back().args[i];
  frames_.pop_back();
}

}  // namespace kerf::job
