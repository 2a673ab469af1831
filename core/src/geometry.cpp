// The geometry helpers callers link against, for each scalar type the core
// is built for.
#include "kerf/core/fixed.hpp"
#include "kerf/geom/circle.hpp"
#include "kerf/geom/segment.hpp"
#include "scalar_types.hpp"

namespace kerf {

#define KERF_GEOMETRY_INSTANCES(S)                                                  \
  template Result<Circle<S>> circle_through(Vec2<S>, Vec2<S>, Vec2<S>);             \
  template S distance_to_segment(const Segment<S>&, Vec2<S>);                       \
  template S distance_to_line_segment(Vec2<S>, Vec2<S>, Vec2<S>);                   \
  template S distance_to_circle(Vec2<S>, Vec2<S>, Vec2<S>);

KERF_FOR_EACH_SCALAR(KERF_GEOMETRY_INSTANCES)

}  // namespace kerf
