#include "config/config.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "config/sections.hpp"
#include "config/table_reader.hpp"

namespace kerf::config {

namespace {

constexpr std::size_t kMaxFileBytes = 1 << 20;  // a config, not a data file

// A reader over root[key], or over an empty table when the section is absent
// (its values keep their defaults).
TableReader section(TableReader& root, const char* key, const toml::table& empty) {
  const toml::table* t = root.table(key);
  return TableReader(t ? *t : empty, key, t ? line_of(*t, 1) : 1, root.problems());
}

bool read_file(const std::string& path, std::string& text, std::string& error) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) {
    error = path + ": cannot read: " + std::strerror(errno);
    return false;
  }
  text.clear();
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) {
    text.append(buf, n);
    if (text.size() > kMaxFileBytes) {
      std::fclose(f);
      error = path + ": cannot read: larger than 1 MiB";
      return false;
    }
  }
  const bool failed = std::ferror(f) != 0;
  const int err = errno;  // EISDIR for a directory
  std::fclose(f);
  if (failed) {
    error = path + ": cannot read: " + std::strerror(err);
    return false;
  }
  return true;
}

// The line of the first non-ASCII byte toml++ 3.3 would test as whitespace,
// or 0. Its is_non_ascii_horizontal_whitespace() reaches
// __builtin_unreachable() for most code points from U+00A1 on (undefined
// behaviour; found by tests/fuzz/fuzz_config), and it is asked wherever
// whitespace may stand: outside strings and comments, and after a
// line-ending backslash in a """ string. TOML allows non-ASCII only inside
// strings and comments, so refusing it elsewhere refuses no valid file.
std::size_t unsafe_non_ascii_line(const std::string& t) {
  std::size_t line = 1;
  auto at = [&](std::size_t i, const char* s) { return t.compare(i, std::strlen(s), s) == 0; };
  for (std::size_t i = 0; i < t.size(); ++i) {
    const char c = t[i];
    if (c == '\n') {
      ++line;
    } else if (static_cast<unsigned char>(c) >= 0x80) {
      return line;
    } else if (c == '#') {  // a comment, to the end of the line
      while (i + 1 < t.size() && t[i + 1] != '\n') ++i;
    } else if (c == '"' || c == '\'') {
      const bool multi = at(i, c == '"' ? "\"\"\"" : "\'\'\'");
      const std::string close = multi ? std::string(3, c) : std::string(1, c);
      for (i += close.size(); i < t.size() && !at(i, close.c_str()); ++i) {
        if (t[i] == '\n') {
          ++line;
          if (!multi) break;  // unterminated: toml++ reports it
        } else if (t[i] == '\\' && c == '"') {
          ++i;  // an escape; after a line-ending one, blanks are skipped
          if (multi && i < t.size() && static_cast<unsigned char>(t[i]) >= 0x80) return line;
          std::size_t k = i;
          while (multi && k < t.size() && (t[k] == ' ' || t[k] == '\t' || t[k] == '\r' || t[k] == '\n')) {
            if (t[k] == '\n') ++line;
            ++k;
          }
          if (multi && k > i && k < t.size() && static_cast<unsigned char>(t[k]) >= 0x80) return line;
          if (multi && k > i) i = k - 1;
        }
      }
      if (multi && i < t.size()) i += 2;
    }
  }
  return 0;
}

}  // namespace

Config defaults() {
  Config c;
  c.file = "(defaults)";
  c.machine.axes = {{"x", 1000}, {"y", 1000}};
  return c;
}

bool parse(const std::string& text, const std::string& display_name, Config& out,
           std::string& error) {
  if (const std::size_t line = unsafe_non_ascii_line(text); line != 0) {
    error = display_name + ":" + std::to_string(line) +
            ": syntax error: a non-ASCII character outside a string or comment";
    return false;
  }
  // A malformed file can make toml++ scan a "string" as a bad value and test
  // its characters as whitespace, so the text goes first with every
  // non-ASCII byte as 'x' (same lines and columns): toml++ sees the real
  // text only once its structure is known to be good.
  std::string ascii = text;
  for (char& ch : ascii)
    if (static_cast<unsigned char>(ch) >= 0x80) ch = 'x';
  if (ascii != text) {
    if (toml::parse_result pre = toml::parse(std::string_view(ascii), std::string_view(display_name));
        !pre) {
      error = display_name + ":" + std::to_string(pre.error().source().begin.line) +
              ": syntax error: " + std::string(pre.error().description());
      return false;
    }
  }
  toml::parse_result parsed = toml::parse(std::string_view(text), std::string_view(display_name));
  if (!parsed) {
    const toml::parse_error& e = parsed.error();
    error = display_name + ":" + std::to_string(e.source().begin.line) +
            ": syntax error: " + std::string(e.description());
    return false;
  }
  // Everything goes into a copy: `out` is untouched unless the whole file is good.
  Config c = defaults();
  c.file = display_name;
  Problems problems;
  const toml::table empty;
  TableReader root(parsed.table(), "", 1, problems);
  TableReader machine = section(root, "machine", empty);
  TableReader link = section(root, "link", empty);
  TableReader gpio = section(root, "gpio", empty);
  TableReader fit = section(root, "fit", empty);
  TableReader cut = section(root, "cut", empty);
  TableReader rt = section(root, "rt", empty);
  TableReader bench = section(root, "bench", empty);
  const bool has_link = parsed.table()["link"].is_table();
  read_program(root, c.program, c.sim);
  if (!root.has("link"))
    problems.add(1, "link", "missing: the machine needs a link ([link] with kind = "
                            "\"modbus-tcp\", \"modbus-rtu\" or \"can\")");
  root.finish();

  std::vector<LineUse> gpio_lines;
  read_machine(machine, c.machine);
  if (has_link) read_link(link, c.link);
  read_gpio(gpio, c.gpio, gpio_lines);
  read_fit(fit, c.fit);
  read_cut(cut, c.cut);
  read_rt(rt, c.rt);
  read_bench(bench, c.bench);

  if (!problems.any()) {
    check_machine(machine, c.machine);
    check_link(link, c.link, machine, c.machine);
    check_gpio(gpio_lines, problems);
    check_program_outputs(gpio_lines, c.program, problems);
    check_cut(cut, c.cut, machine, c.machine);
  }
  if (problems.any()) {
    error = problems.first(display_name);
    return false;
  }
  out = std::move(c);
  return true;
}

bool load(const std::string& path, Config& out, std::string& error) {
  std::string text;
  if (!read_file(path, text, error)) return false;
  return parse(text, path, out, error);
}

}  // namespace kerf::config
