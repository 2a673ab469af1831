#include "kerf/hal/gpio/gpio_lines.hpp"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace kerf::hal::gpio_lines {

namespace {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

std::string prefix(const std::string& role) { return "gpio: " + role + ": "; }

bool all_digits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// gpiochip12 -> 12, for sorting; anything else sorts last.
long chip_number(const std::string& path) {
  const auto pos = path.rfind("gpiochip");
  const std::string tail = pos == std::string::npos ? "" : path.substr(pos + 8);
  return all_digits(tail) ? std::strtol(tail.c_str(), nullptr, 10) : 1L << 30;
}

bool add_line(const std::string& role, const GpioLineConfig& line, bool output, int limit_index,
              std::vector<LineRole>& out, std::string& error, int number = -1) {
  if (!line.used) return true;
  if (line.offset < 0 && line.name.empty()) {
    error = prefix(role) + "neither an offset nor a line name is set";
    return false;
  }
  if (!std::isfinite(line.debounce_s) || line.debounce_s < 0.0) {
    error = prefix(role) + "debounce must be a time >= 0 s";
    return false;
  }
  out.push_back(LineRole{role, &line, output, limit_index, number});
  return true;
}

// Program outputs or inputs: numbers 0..255, each once.
bool add_program_lines(const char* kind, const std::vector<GpioProgramLine>& lines, bool output,
                       std::vector<LineRole>& out, std::string& error) {
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int n = lines[i].number;
    const std::string role = std::string(kind) + " " + std::to_string(n);
    if (n < 0 || n > 255) {
      error = prefix(role) + "the number must be 0..255";
      return false;
    }
    for (std::size_t j = 0; j < i; ++j)
      if (lines[j].number == n) {
        error = prefix(role) + "configured twice";
        return false;
      }
    if (!add_line(role, lines[i].line, output, -1, out, error, n)) return false;
  }
  return true;
}

}  // namespace

bool list_lines(const GpioConfig& cfg, std::vector<LineRole>& out, std::string& error) {
  out.clear();
  if (cfg.limits.size() > kMaxLimitLines) {
    error = "gpio: " + std::to_string(cfg.limits.size()) + " limit lines, at most " +
            std::to_string(kMaxLimitLines);
    return false;
  }
  if (!add_line("torch", cfg.torch, true, -1, out, error)) return false;
  if (!add_line("arc_ok", cfg.arc_ok, false, -1, out, error)) return false;
  if (!add_line("estop", cfg.estop, false, -1, out, error)) return false;
  for (std::size_t i = 0; i < cfg.limits.size(); ++i) {
    const int index = static_cast<int>(i);
    if (!add_line("limit " + std::to_string(i), cfg.limits[i], false, index, out, error))
      return false;
  }
  if (!add_line("hold", cfg.hold, false, -1, out, error)) return false;
  if (!add_line("cycle_start", cfg.cycle_start, false, -1, out, error)) return false;
  if (!add_line("reset", cfg.reset, false, -1, out, error)) return false;
  if (!add_line("watchdog", cfg.watchdog, true, -1, out, error)) return false;
  if (!add_line("thc_lock", cfg.thc_lock, true, -1, out, error)) return false;
  return add_program_lines("output", cfg.outputs, true, out, error) &&
         add_program_lines("input", cfg.inputs, false, out, error);
}

std::string chip_path_for(const std::string& spec) {
  if (spec.empty()) return "";
  if (spec.find('/') != std::string::npos) return spec;
  if (all_digits(spec)) return "/dev/gpiochip" + spec;
  if (spec.rfind("gpiochip", 0) == 0 && all_digits(spec.substr(8))) return "/dev/" + spec;
  return "";
}

std::vector<std::string> list_chip_paths(const char* dev_dir) {
  std::vector<std::string> paths;
  DIR* dir = ::opendir(dev_dir);
  if (dir == nullptr) return paths;
  while (const dirent* e = ::readdir(dir)) {
    if (std::strncmp(e->d_name, "gpiochip", 8) != 0) continue;
    std::string path = std::string(dev_dir) + "/" + e->d_name;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode)) paths.push_back(std::move(path));
  }
  ::closedir(dir);
  std::sort(paths.begin(), paths.end(), [](const std::string& a, const std::string& b) {
    const long na = chip_number(a), nb = chip_number(b);
    return na != nb ? na < nb : a < b;
  });
  return paths;
}

bool check_offset(const std::string& role, const ChipInfo& chip, int offset, std::string& error) {
  if (offset >= 0 && offset < chip.num_lines) return true;
  error = prefix(role) + "chip " + chip.name + " has " + std::to_string(chip.num_lines) +
          " lines, offset " + std::to_string(offset) + " is out of range";
  return false;
}

bool check_distinct(const std::vector<LineRole>& roles, const std::vector<LineAddress>& where,
                    std::string& error) {
  for (std::size_t i = 0; i < where.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (where[i].chip == where[j].chip && where[i].offset == where[j].offset) {
        error = prefix(roles[i].role) + "line " + std::to_string(where[i].offset) + " on " +
                where[i].chip + " is already " + roles[j].role + "'s";
        return false;
      }
  return true;
}

std::string no_such_chip(const std::string& role, const std::string& spec) {
  return prefix(role) + "no such chip " + quoted(spec);
}

std::string not_a_chip(const std::string& role, const std::string& path) {
  return prefix(role) + path + " is not a GPIO chip";
}

std::string cannot_open(const std::string& role, const std::string& path, int err) {
  return prefix(role) + "cannot open " + path + ": " + std::strerror(err);
}

std::string busy(const std::string& role, const std::string& chip, int offset,
                 const std::string& consumer) {
  std::string text = prefix(role) + "line " + std::to_string(offset) + " on " + chip + " is busy";
  if (!consumer.empty()) text += " (used by " + quoted(consumer) + ")";
  return text;
}

std::string name_not_found(const std::string& role, const std::string& name,
                           const std::vector<ChipInfo>& searched, bool chip_given) {
  std::string text = prefix(role) + "no line named " + quoted(name);
  if (chip_given && searched.size() == 1) return text + " on " + searched[0].name;
  if (searched.empty()) return text + " (no GPIO chips found under /dev)";
  text += " on any of " + std::to_string(searched.size()) + " chips (";
  for (std::size_t i = 0; i < searched.size(); ++i)
    text += (i == 0 ? "" : ", ") + searched[i].name;
  return text + ")";
}

std::string name_ambiguous(const std::string& role, const std::string& name,
                           const std::string& chip_a, const std::string& chip_b) {
  return prefix(role) + "line name " + quoted(name) + " is on both " + chip_a + " and " + chip_b +
         ": set the chip";
}

std::string request_failed(const std::string& role, const std::string& chip, int offset, int err) {
  return prefix(role) + "cannot request line " + std::to_string(offset) + " on " + chip + ": " +
         std::strerror(err);
}

}  // namespace kerf::hal::gpio_lines
