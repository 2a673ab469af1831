#include "io/fit_deviation.hpp"

#include <cmath>
#include <limits>

#include "kerf/geom/segment.hpp"

namespace kerf::io {

namespace {

// Which side of the piece p lies on: +1 left of travel, -1 right.
double side(const Segment<double>& s, Vec2<double> p) {
  if (!s.is_arc()) return (s.end - s.start).cross(p - s.start) >= 0 ? 1.0 : -1.0;
  // Travelling counter-clockwise, the centre is on the left.
  const bool inside = (p - s.centre).norm() <= s.radius();
  return (inside == (s.dir > 0)) ? 1.0 : -1.0;
}

}  // namespace

std::vector<double> signed_deviations(Span<const Vec2<double>> points,
                                      Span<const fit::Piece<double>> pieces) {
  std::vector<double> dev(points.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<double> best(points.size(), std::numeric_limits<double>::infinity());
  for (const fit::Piece<double>& pc : pieces) {
    for (std::size_t i = pc.first; i <= pc.last && i < points.size(); ++i) {
      const double d = distance_to_segment(pc.segment, points[i]);
      if (!(d < best[i])) continue;
      best[i] = d;
      dev[i] = d * side(pc.segment, points[i]);
    }
  }
  return dev;
}

}  // namespace kerf::io
