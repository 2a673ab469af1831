// The [gpio] section: the default chip, one table per line, and the limit
// switches as an array of tables.
#include <algorithm>
#include <string>
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

// Reads one line's table (`path`: gpio.torch, gpio.limit[0], ...). With
// `number` (gpio.output[i], gpio.input[i]) the table also holds the program
// number (M62..M66 P), required.
hal::GpioLineConfig read_line(const toml::table& t, const std::string& path, std::uint32_t line,
                              const std::string& default_chip, bool is_output, Problems& problems,
                              std::vector<LineUse>& uses, int* number = nullptr) {
  TableReader r(t, path, line, problems);
  hal::GpioLineConfig c;
  c.used = true;
  if (number != nullptr && !r.integer("number", *number, 0, 255) && !r.has("number"))
    problems.add(line, path, std::string("needs number (the ") + (is_output ? "M62..M65" : "M66") + " P number)");
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
                    r.line(has_offset ? "offset" : "name"), -1, is_output, 0});
  }
  return c;
}

struct NamedLine {
  const char* key;
  hal::GpioLineConfig hal::GpioConfig::*field;
  bool is_output;
};

// An array of line tables ([[gpio.limit]], [[gpio.output]], [[gpio.input]]):
// `each(table, path, line)` for every table, at most `max` of them.
template <class Each>
void read_line_array(TableReader& r, const char* key, const char* expected, std::size_t max, Each each) {
  const toml::array* lines = r.array(key, expected);
  if (lines == nullptr) return;
  for (std::size_t i = 0; i < lines->size(); ++i) {
    const toml::node& node = *lines->get(i);
    const std::string path = r.key_path(key) + "[" + std::to_string(i) + "]";
    const std::uint32_t line = line_of(node, r.line(key));
    if (i == max) {
      r.problems().add(line, r.key_path(key),
                       "at most " + std::to_string(max) + " " + key + " lines, got " + std::to_string(lines->size()));
      return;
    }
    if (const toml::table* t = node.as_table()) each(*t, path, line);
    else r.problems().add(line, path, std::string("expected a table, got ") + type_phrase(node));
  }
}

// [[gpio.output]] / [[gpio.input]]: numbered program lines, each number once.
void read_program_lines(TableReader& r, const char* key, bool is_output, const std::string& chip,
                        std::vector<hal::GpioProgramLine>& out, std::vector<LineUse>& uses) {
  const std::string expected = std::string("an array of tables ([[gpio.") + key + "]])";
  read_line_array(r, key, expected.c_str(), 256, [&](const toml::table& t, const std::string& path, std::uint32_t line) {
    hal::GpioProgramLine p;
    p.number = -1;
    p.line = read_line(t, path, line, chip, is_output, r.problems(), uses, &p.number);
    if (p.number < 0) return;
    for (const hal::GpioProgramLine& q : out)
      if (q.number == p.number)
        r.problems().add(line_of(*t.get("number"), line), path + ".number",
                         std::string(key) + " " + std::to_string(p.number) + " is configured twice");
    out.push_back(p);
    if (!uses.empty() && uses.back().path == path) {
      uses.back().number = p.number;
      uses.back().number_line = line_of(*t.get("number"), line);
    }
  });
}

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
  if (r.has("limit")) gpio.limits.clear();
  read_line_array(r, "limit", "an array of tables ([[gpio.limit]])", hal::kMaxLimitLines,
                  [&](const toml::table& t, const std::string& path, std::uint32_t line) {
                    gpio.limits.push_back(read_line(t, path, line, chip, false, r.problems(), uses));
                  });
  read_program_lines(r, "output", true, chip, gpio.outputs, uses);
  read_program_lines(r, "input", false, chip, gpio.inputs, uses);
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

void check_program_outputs(const std::vector<LineUse>& uses, const Program& p, Problems& problems) {
  for (const LineUse& u : uses)
    if (u.output && u.number >= 0 && u.number == p.torch_output)
      problems.add(u.number_line, u.path + ".number",
                   "output " + std::to_string(u.number) + " is outputs.torch, which gpio.torch drives: remove one");
}

}  // namespace kerf::config
