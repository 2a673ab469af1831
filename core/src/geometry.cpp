// The double instantiation of the geometry helpers callers link against.
#include "kerf/geom/circle.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf {

template Result<Circle<double>> circle_through(Vec2<double>, Vec2<double>, Vec2<double>);
template double distance_to_segment(const Segment<double>&, Vec2<double>);
template double distance_to_line_segment(Vec2<double>, Vec2<double>, Vec2<double>);
template double distance_to_circle(Vec2<double>, Vec2<double>, Vec2<double>);

}  // namespace kerf
