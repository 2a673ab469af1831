// The [gpio] section: the default chip, one table per line, and the limit
// switches as an array of tables.
#include <algorithm>
#include <string_view>

#include "config/sections.hpp"

namespace kerf::config {

namespace {

constexpr int kMaxOffset = 65535;
constexpr double kMaxDebounceMs = 1000;

std::string bare_chip(std::string chip) {
  constexpr std::string_view kDev = "/dev/";
  if (chip.rfind(kDev, 0) == 0) chip.erase(0, kDev.size());
  return chip;
}

// Reads one line's table (`path`: gpio.torch, gpio.limit[0], ...).
hal::GpioLineConfig read_line(const toml::table& t, const std::string& path, std::uint32_t line,
                              const std::string& default_chip, bool is_output, Problems& problems,
                              std::vector<LineUse>& uses) {
  TableReader r(t, path, line, problems);
  hal::GpioLineConfig c;
  c.used = true;
  c.chip = default_chip;
  r.string("chip", c.chip);
  const bool has_offset = r.integer("offset", c.offset, 0, kMaxOffset);
  const bool has_name = r.string("name", c.name);
  r.boolean("active_low", c.active_low);
  if (is_output) {
    if (r.has("debounce_ms")) {
      r.known("debounce_ms");
      r.problem("debounce_ms", "not for an output");
    }
  } else {
    double ms = 0;
    if (r.number_in("debounce_ms", ms, 0, kMaxDebounceMs)) c.debounce_s = ms / 1000;
  }
  r.finish();

  if (!r.has("offset") && !r.has("name")) {
    problems.add(line, path, "needs offset (with a chip) or name");
  } else if (r.has("offset") && r.has("name")) {
    r.problem("name", "give offset or name, not both");
  } else if (has_offset && c.chip.empty()) {
    r.problem("offset", "needs a chip: set gpio.chip or " + path + ".chip");
  }
  if (has_offset || has_name) {
    c.offset = has_offset ? c.offset : -1;
    uses.push_back({path, bare_chip(c.chip), c.offset, has_offset ? "" : c.name,
                    r.line(has_offset ? "offset" : "name")});
  }
  return c;
}

struct NamedLine {
  const char* key;
  hal::GpioLineConfig hal::GpioConfig::*field;
  bool is_output;
};

}  // namespace

void read_gpio(TableReader& r, hal::GpioConfig& gpio, std::vector<LineUse>& uses) {
  r.string("consumer", gpio.consumer);
  std::string chip;  // empty: lines by name are searched on every chip
  r.string("chip", chip);
  static constexpr std::array<NamedLine, 8> kLines = {{
      {"torch", &hal::GpioConfig::torch, true},
      {"arc_ok", &hal::GpioConfig::arc_ok, false},
      {"estop", &hal::GpioConfig::estop, false},
      {"hold", &hal::GpioConfig::hold, false},
      {"cycle_start", &hal::GpioConfig::cycle_start, false},
      {"reset", &hal::GpioConfig::reset, false},
      {"watchdog", &hal::GpioConfig::watchdog, true},
      {"thc_lock", &hal::GpioConfig::thc_lock, true},
  }};
  for (const auto& l : kLines) {
    if (const toml::table* t = r.table(l.key))
      gpio.*l.field = read_line(*t, r.key_path(l.key), line_of(*t, r.line(l.key)), chip,
                                l.is_output, r.problems(), uses);
  }
  if (const toml::array* limits = r.array("limit", "an array of tables ([[gpio.limit]])")) {
    gpio.limits.clear();
    for (std::size_t i = 0; i < limits->size(); ++i) {
      const toml::node& node = *limits->get(i);
      const std::string path = r.key_path("limit") + "[" + std::to_string(i) + "]";
      const std::uint32_t line = line_of(node, r.line("limit"));
      if (i == hal::kMaxLimitLines) {
        r.problems().add(line, r.key_path("limit"),
                         "at most " + std::to_string(hal::kMaxLimitLines) + " limit lines, got " +
                             std::to_string(limits->size()));
        break;
      }
      const toml::table* t = node.as_table();
      if (!t) {
        r.problems().add(line, path, std::string("expected a table, got ") + type_phrase(node));
        continue;
      }
      gpio.limits.push_back(read_line(*t, path, line, chip, false, r.problems(), uses));
    }
  }
  r.finish();
}

void check_gpio(const std::vector<LineUse>& uses, Problems& problems) {
  std::vector<const LineUse*> in_file_order;
  for (const auto& u : uses) in_file_order.push_back(&u);
  std::stable_sort(in_file_order.begin(), in_file_order.end(),
                   [](const LineUse* a, const LineUse* b) { return a->line < b->line; });
  for (std::size_t j = 0; j < in_file_order.size(); ++j) {
    const LineUse& later = *in_file_order[j];
    for (std::size_t i = 0; i < j; ++i) {
      const LineUse& earlier = *in_file_order[i];
      if (earlier.chip != later.chip || earlier.offset != later.offset || earlier.name != later.name)
        continue;
      const std::string where = later.chip.empty() ? "any chip" : later.chip;
      if (later.offset >= 0)
        problems.add(later.line, later.path + ".offset",
                     "line " + std::to_string(later.offset) + " of " + where + " is already " +
                         earlier.path);
      else
        problems.add(later.line, later.path + ".name",
                     "line " + quote(later.name) + " on " + where + " is already " + earlier.path);
      break;
    }
  }
}

}  // namespace kerf::config
