#include "job/machine_state.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace kerf::job {

namespace {

const char* const kNames[kCoordSystems] = {"G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"};

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") + 1 - a);
}

// n numbers separated by blanks; false unless exactly n finite numbers.
bool numbers(const std::string& text, double* out, int n) {
  const char* p = text.c_str();
  for (int i = 0; i < n; ++i) {
    char* end = nullptr;
    errno = 0;
    out[i] = std::strtod(p, &end);
    if (end == p || errno != 0) return false;
    p = end;
  }
  while (*p == ' ' || *p == '\t') ++p;
  return *p == '\0';
}

}  // namespace

const char kAxisNames[3] = {'x', 'y', 'z'};

std::string homed_names(const MachineState& s, int n) {
  std::string out;
  for (int a = 0; a < n && a < 3; ++a)
    if (s.homed[a]) {
      if (!out.empty()) out += ' ';
      out += kAxisNames[a];
    }
  return out;
}

bool all_homed(const MachineState& s, int n) {
  for (int a = 0; a < n && a < 3; ++a)
    if (!s.homed[a]) return false;
  return true;
}

const char* coord_name(int k) { return k >= 0 && k < kCoordSystems ? kNames[k] : "?"; }

std::string format_machine_state(const MachineState& s) {
  std::string out = "# kerf machine state: work offsets in mm (x y z); written by kerf run\n";
  char buf[160];
  for (int k = 0; k < kCoordSystems; ++k) {
    std::snprintf(buf, sizeof buf, "%s = %.17g %.17g %.17g\n", kNames[k], s.g5x[k][0], s.g5x[k][1], s.g5x[k][2]);
    out += buf;
  }
  std::snprintf(buf, sizeof buf, "G92 = %.17g %.17g %.17g\n", s.g92[0], s.g92[1], s.g92[2]);
  out += buf;
  out += std::string("g92_on = ") + (s.g92_on ? "1" : "0") + "\n";
  out += std::string("coord = ") + kNames[s.coord] + "\n";
  out += "homed = " + homed_names(s, 3) + "\n";
  if (s.has_position) {
    std::snprintf(buf, sizeof buf, "position = %.17g %.17g %.17g\n", s.position[0], s.position[1], s.position[2]);
    out += buf;
  }
  for (const auto& [k, v] : s.other) out += k + " = " + v + "\n";
  return out;
}

bool load_machine_state(const std::string& path, MachineState& out, std::string& error) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) {
    if (errno == ENOENT) {
      out = MachineState{};
      return true;
    }
    error = path + ": cannot read: " + std::strerror(errno);
    return false;
  }
  MachineState s;
  char buf[512];
  std::size_t line = 0;
  bool ok = true;
  while (ok && std::fgets(buf, sizeof buf, f) != nullptr) {
    ++line;
    const std::string text = trim(buf);
    if (text.empty() || text[0] == '#') continue;
    const std::size_t eq = text.find('=');
    auto bad = [&](const std::string& why) {
      error = path + ":" + std::to_string(line) + ": " + why;
      ok = false;
    };
    if (eq == std::string::npos) {
      bad("expected KEY = VALUE");
      continue;
    }
    const std::string key = trim(text.substr(0, eq)), value = trim(text.substr(eq + 1));
    bool known = false;
    for (int k = 0; k < kCoordSystems; ++k)
      if (key == kNames[k]) {
        known = true;
        if (!numbers(value, s.g5x[k], 3)) bad(key + ": expected three numbers (x y z mm)");
      }
    if (known) continue;
    if (key == "G92") {
      if (!numbers(value, s.g92, 3)) bad("G92: expected three numbers (x y z mm)");
    } else if (key == "g92_on") {
      if (value != "0" && value != "1") bad("g92_on: expected 0 or 1");
      s.g92_on = value == "1";
    } else if (key == "coord") {
      int found = -1;
      for (int k = 0; k < kCoordSystems; ++k)
        if (value == kNames[k]) found = k;
      if (found < 0) bad("coord: expected G54 .. G59.3, got \"" + value + "\"");
      else s.coord = found;
    } else if (key == "homed") {
      for (std::size_t i = 0; i < value.size(); ++i) {
        const char c = value[i];
        if (c == ' ' || c == '\t') continue;
        const bool name = c == 'x' || c == 'y' || c == 'z';
        const bool alone = i + 1 == value.size() || value[i + 1] == ' ' || value[i + 1] == '\t';
        if (!name || !alone) {
          bad("homed: expected axis names (x y z) separated by blanks, got \"" + value + "\"");
          break;
        }
        s.homed[c - 'x'] = true;
      }
    } else if (key == "position") {
      if (!numbers(value, s.position, 3)) bad("position: expected three numbers (x y z mm)");
      s.has_position = true;
    } else {
      s.other.emplace_back(key, value);
    }
  }
  std::fclose(f);
  if (ok) out = s;
  return ok;
}

bool save_machine_state(const std::string& path, const MachineState& s, std::string& error) {
  const std::string tmp = path + ".tmp";
  const std::string text = format_machine_state(s);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    error = tmp + ": cannot write: " + std::strerror(errno);
    return false;
  }
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  const bool written = done == text.size() && ::fsync(fd) == 0;
  const int err = errno;
  ::close(fd);
  if (!written || std::rename(tmp.c_str(), path.c_str()) != 0) {
    error = path + ": cannot write: " + std::strerror(written ? errno : err);
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

}  // namespace kerf::job
