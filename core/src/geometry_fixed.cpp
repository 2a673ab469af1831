// The fixed-point (kerf::Fixed) instantiation of the geometry helpers callers link against.
#include "kerf/core/fixed.hpp"
#include "kerf/geom/circle.hpp"
#include "kerf/core/fixed.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf {

template Result<Circle<Fixed>> circle_through(Vec2<Fixed>, Vec2<Fixed>, Vec2<Fixed>);
template Fixed distance_to_segment(const Segment<Fixed>&, Vec2<Fixed>);
template Fixed distance_to_line_segment(Vec2<Fixed>, Vec2<Fixed>, Vec2<Fixed>);
template Fixed distance_to_circle(Vec2<Fixed>, Vec2<Fixed>, Vec2<Fixed>);

}  // namespace kerf
