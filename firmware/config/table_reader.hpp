// Typed reads from one TOML table, for config/. Every key a reader asks for
// is marked known; finish() reports the rest as unknown keys, so a typo
// never leaves a default silently in place. Problems are collected with
// their line; the config reports the first one in the file.
#pragma once

#include "io/quote.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "config/tomlpp.hpp"

namespace kerf::config {

struct Problem {
  std::uint32_t line = 0;
  std::string key;     // dotted path, e.g. machine.axis[1].counts_per_mm
  std::string reason;
};

class Problems {
 public:
  void add(std::uint32_t line, std::string key, std::string reason);
  bool any() const { return !list_.empty(); }
  // "FILE:LINE: KEY: reason" for the problem that comes first in the file.
  std::string first(const std::string& file) const;

 private:
  std::vector<Problem> list_;
};

// The line a node starts on; `fallback` for nodes without a source (tables
// that toml++ created implicitly, e.g. `a` for `[a.b]`).
std::uint32_t line_of(const toml::node& n, std::uint32_t fallback);

// A number as written in messages: the shortest form that reads back exactly.
std::string format_number(double v);

using io::quote;

class TableReader {
 public:
  // `path` is the table's dotted path ("" for the document's root).
  TableReader(const toml::table& table, std::string path, std::uint32_t line, Problems& problems);

  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;
  std::uint32_t line() const { return line_; }
  // The key's line, or the table's when the key is absent.
  std::uint32_t line(std::string_view key) const;
  bool has(std::string_view key) const { return table_.contains(key); }
  Problems& problems() { return problems_; }
  void problem(std::string_view key, std::string reason);

  // Each returns true when the key is present and valid, and only then
  // writes `out`. Absent: false, no problem. Invalid: false, a problem.
  bool number(std::string_view key, double& out);           // finite; integers accepted
  bool positive(std::string_view key, double& out);         // > 0
  bool non_negative(std::string_view key, double& out);     // >= 0
  bool positive_at_most(std::string_view key, double& out, double max);  // (0, max]
  bool number_in(std::string_view key, double& out, double lo, double hi);  // [lo, hi]
  bool integer(std::string_view key, int& out, int lo, int hi);
  bool string(std::string_view key, std::string& out);      // not empty
  bool boolean(std::string_view key, bool& out);
  // Sub-tables and arrays: null when absent or of the wrong type (a problem).
  const toml::table* table(std::string_view key);
  const toml::array* array(std::string_view key, std::string_view expected);

  // Marks a key known without reading it (read elsewhere, or refused by the caller).
  void known(std::string_view key);
  // Reports every key that was never asked for.
  void finish();

 private:
  const toml::node* get(std::string_view key, bool mark);
  void wrong_type(std::string_view key, const toml::node& n, std::string_view expected);
  // The value at `key` as a T (std::int64_t, std::string, bool, toml::table),
  // marked as read; null when missing, or of another type (then the problem
  // "must be <expected>").
  template <class T>
  auto typed(std::string_view key, std::string_view expected);
  // number(key) inside lo..hi (lo itself only if !lo_open); else the problem
  // "must be <must>, got V".
  bool number_within(std::string_view key, double& out, double lo, bool lo_open, double hi,
                     const std::string& must);

  const toml::table& table_;
  std::string path_;
  std::uint32_t line_;
  Problems& problems_;
  std::vector<std::string> known_;
};

// "a string", "an integer", ...: what a node is, for "expected X, got Y".
const char* type_phrase(const toml::node& n);

}  // namespace kerf::config
