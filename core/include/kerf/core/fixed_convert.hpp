// Conversions between kerf::Fixed and double for host code (the CLI, tests,
// verification). They use floating point, so the core never includes this.
#pragma once

#include "kerf/core/fixed.hpp"

namespace kerf {

inline double to_double(Fixed v) { return static_cast<double>(v.raw()) / 4294967296.0; }

// Rounds to the nearest step; out of range (or NaN) saturates like overflow.
inline Fixed fixed_from_double(double v) {
  const double scaled = v * 4294967296.0;
  if (!(scaled < 9.2e18)) return scaled < 0 ? Fixed::lowest() : Fixed::max();
  if (!(scaled > -9.2e18)) return Fixed::lowest();
  return Fixed::from_raw(static_cast<std::int64_t>(scaled < 0 ? scaled - 0.5 : scaled + 0.5));
}

// The coarsest of the two: what one conversion of a coordinate may move it.
inline constexpr double fixed_quantum = 1.0 / 4294967296.0;

}  // namespace kerf
