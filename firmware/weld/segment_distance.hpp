// The distance from many points to one segment, as write_piece measures its
// samples (weld/weld_plan.cpp).
#pragma once

#include <cmath>

#include "kerf/geom/segment.hpp"

namespace kerf::weld::detail {

// distance_to_line_segment(a, b, p) (kerf/geom/segment.hpp) with the
// segment's own terms computed once: the same operations, so the same value
// bit for bit (tests/weld/test_segment_distance.cpp).
struct SegmentDistance {
  Vec2<double> a, b, d;
  double len2, len;
  SegmentDistance(Vec2<double> from, Vec2<double> to)
      : a(from), b(to), d(to - from), len2(d.norm2()), len(std::sqrt(len2)) {}
  double operator()(Vec2<double> p) const {
    if (len2 == 0) return distance(a, p);
    const double t = d.dot(p - a);
    if (t <= 0) return distance(a, p);
    if (t >= len2) return distance(b, p);
    return std::fabs(d.cross(p - a)) / len;
  }
};

}  // namespace kerf::weld::detail
