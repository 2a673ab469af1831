#include "config/table_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace kerf::config {

void Problems::add(std::uint32_t line, std::string key, std::string reason) {
  list_.push_back({line, std::move(key), std::move(reason)});
}

std::string Problems::first(const std::string& file) const {
  if (list_.empty()) return {};
  // stable: of two problems on one line, the one found first (the order the
  // sections are read in) wins.
  const auto it = std::min_element(list_.begin(), list_.end(),
                                   [](const Problem& a, const Problem& b) { return a.line < b.line; });
  return file + ":" + std::to_string(it->line) + ": " + it->key + ": " + it->reason;
}

std::uint32_t line_of(const toml::node& n, std::uint32_t fallback) {
  const auto line = n.source().begin.line;
  return line > 0 ? line : fallback;
}

std::string format_number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[40];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}


const char* type_phrase(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    case toml::node_type::none: break;
  }
  return "nothing";
}

TableReader::TableReader(const toml::table& table, std::string path, std::uint32_t line,
                         Problems& problems)
    : table_(table), path_(std::move(path)), line_(line), problems_(problems) {}

std::string TableReader::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

std::uint32_t TableReader::line(std::string_view key) const {
  const toml::node* n = table_.get(key);
  return n ? line_of(*n, line_) : line_;
}

void TableReader::problem(std::string_view key, std::string reason) {
  problems_.add(line(key), key_path(key), std::move(reason));
}

void TableReader::known(std::string_view key) { known_.emplace_back(key); }

const toml::node* TableReader::get(std::string_view key, bool mark) {
  if (mark) known(key);
  return table_.get(key);
}

void TableReader::wrong_type(std::string_view key, const toml::node& n, std::string_view expected) {
  problem(key, "expected " + std::string(expected) + ", got " + type_phrase(n));
}

bool TableReader::number(std::string_view key, double& out) {
  const toml::node* n = get(key, true);
  if (!n) return false;
  double v = 0;
  if (const auto* i = n->as_integer()) {
    v = static_cast<double>(i->get());
  } else if (const auto* f = n->as_floating_point()) {
    v = f->get();
  } else {
    wrong_type(key, *n, "a number");
    return false;
  }
  if (!std::isfinite(v)) {
    problem(key, "must be a finite number, got " + format_number(v));
    return false;
  }
  out = v;
  return true;
}

bool TableReader::number_within(std::string_view key, double& out, double lo, bool lo_open, double hi,
                                const std::string& must) {
  double v = 0;
  if (!number(key, v)) return false;
  if (!((lo_open ? v > lo : v >= lo) && v <= hi)) {
    problem(key, "must be " + must + ", got " + format_number(v));
    return false;
  }
  out = v;
  return true;
}

bool TableReader::positive(std::string_view key, double& out) {
  return number_within(key, out, 0, true, HUGE_VAL, "> 0");
}

bool TableReader::non_negative(std::string_view key, double& out) {
  return number_within(key, out, 0, false, HUGE_VAL, ">= 0");
}

bool TableReader::positive_at_most(std::string_view key, double& out, double max) {
  return number_within(key, out, 0, true, max, "in (0, " + format_number(max) + "]");
}

bool TableReader::number_in(std::string_view key, double& out, double lo, double hi) {
  return number_within(key, out, lo, false, hi, "in [" + format_number(lo) + ", " + format_number(hi) + "]");
}

template <class T>
auto TableReader::typed(std::string_view key, std::string_view expected) {
  const toml::node* n = get(key, true);
  const auto* v = n ? n->as<T>() : nullptr;
  if (n && !v) wrong_type(key, *n, expected);
  return v;
}

bool TableReader::integer(std::string_view key, int& out, int lo, int hi) {
  const auto* i = typed<std::int64_t>(key, "an integer");
  if (!i) return false;
  const std::int64_t v = i->get();
  if (v < lo || v > hi) {
    problem(key, "must be in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " +
                     std::to_string(v));
    return false;
  }
  out = static_cast<int>(v);
  return true;
}

bool TableReader::string(std::string_view key, std::string& out) {
  const auto* s = typed<std::string>(key, "a string");
  if (!s) return false;
  if (s->get().empty()) {
    problem(key, "must not be empty");
    return false;
  }
  out = s->get();
  return true;
}

bool TableReader::boolean(std::string_view key, bool& out) {
  const auto* b = typed<bool>(key, "a boolean (true or false)");
  if (!b) return false;
  out = b->get();
  return true;
}

const toml::table* TableReader::table(std::string_view key) { return typed<toml::table>(key, "a table"); }

const toml::array* TableReader::array(std::string_view key, std::string_view expected) {
  const toml::node* n = get(key, true);
  if (!n) return nullptr;
  const auto* a = n->as_array();
  if (!a) wrong_type(key, *n, expected);
  return a;
}

void TableReader::finish() {
  for (const auto& [key, node] : table_) {
    const std::string_view k = key.str();
    if (std::find(known_.begin(), known_.end(), k) == known_.end())
      problems_.add(line_of(node, line_), key_path(k), "unknown key");
  }
}

}  // namespace kerf::config
