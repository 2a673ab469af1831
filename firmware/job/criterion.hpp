// The fit's criterion and scalar type. Text becomes one of these once, where
// it comes in (the command line, the machine configuration); everything past
// that passes the value, and to_string gives the name back for messages and
// reports.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace kerf::job {

// vertex: arcs through input points; band: the whole arc inside the
// tolerance band; biarc: G1 biarcs inside the band (job/fit_job.hpp).
enum class Criterion { vertex, band, biarc };

// floating: IEEE double ("double"); fixed: kerf::Fixed, Q31.32, what a core
// without an FPU runs ("fixed"). Every criterion has both.
enum class Numeric { floating, fixed };

constexpr const char* to_string(Criterion c) {
  switch (c) {
    case Criterion::vertex: return "vertex";
    case Criterion::band: return "band";
    case Criterion::biarc: return "biarc";
  }
  return "?";
}

constexpr const char* to_string(Numeric n) { return n == Numeric::fixed ? "fixed" : "double"; }

inline std::optional<Criterion> parse_criterion(std::string_view text) {
  for (const Criterion c : {Criterion::vertex, Criterion::band, Criterion::biarc})
    if (text == to_string(c)) return c;
  return std::nullopt;
}

inline std::optional<Numeric> parse_numeric(std::string_view text) {
  for (const Numeric n : {Numeric::floating, Numeric::fixed})
    if (text == to_string(n)) return n;
  return std::nullopt;
}

// The command line's messages for a name parse_* refused.
inline std::string unknown_criterion(const std::string& text) {
  return "--criterion: unknown criterion \"" + text + "\" (expected vertex, band or biarc)";
}
inline std::string unknown_numeric(const std::string& text) {
  return "--numeric: unknown type \"" + text + "\" (expected double or fixed)";
}

}  // namespace kerf::job
