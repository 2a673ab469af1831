// Drive counts: integer positions the drives receive. They are rounded from
// the exact commanded position each period, never summed from increments, so
// rounding errors cannot accumulate into drift.
#pragma once

#include <cstdint>

#include "kerf/geom/vec2.hpp"

namespace kerf::motion {

struct Counts {
  std::int64_t x = 0;
  std::int64_t y = 0;
  constexpr bool operator==(const Counts& o) const { return x == o.x && y == o.y; }
};

// Nearest integer, halves away from zero. |v| must be below 2^62.
template <class S>
std::int64_t round_to_count(S v) {
  return v < S(0) ? -static_cast<std::int64_t>(-v + S(0.5)) : static_cast<std::int64_t>(v + S(0.5));
}

template <class S>
Counts to_counts(Vec2<S> position_mm, Vec2<S> counts_per_mm) {
  return {round_to_count(position_mm.x * counts_per_mm.x),
          round_to_count(position_mm.y * counts_per_mm.y)};
}

}  // namespace kerf::motion
