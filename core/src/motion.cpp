// The motion code callers link against, for each scalar type the core is
// built for.
#include "kerf/core/fixed.hpp"
#include "kerf/motion/board_executor.hpp"
#include "kerf/motion/interpolator.hpp"
#include "kerf/motion/interpolator_motion.hpp"
#include "scalar_types.hpp"

namespace kerf::motion {

#define KERF_MOTION_INSTANCES(S)                                                   \
  template class PathQueue<S>;                                                     \
  template class Interpolator<S>;                                                  \
  template Result<QueuedSegment<S>> prepare_segment(const PathSegment<S>&);        \
  template Vec2<S> point_at(const QueuedSegment<S>&, S);                           \
  template SegmentFlaw segment_flaw(const Segment<S>&, SegmentShape<S>&);          \
  template Emitted<S> emit_on_grid(Vec2<S>, const Segment<S>&, const SegmentGrid&); \
  template S braking_length(S, S, S);                                              \
  template S max_step_before(S, S, S);                                             \
  template S turn_chord(Vec2<S>, Vec2<S>);                                          \
  template S joint_step_limit(S, S, S, S, S);                                      \
  template S curve_step_cap(S, S, S);                                              \
  template S tangential_step(S, S);                                                \
  template class InterpolatorMotion<S>;                                            \
  template class BoardExecutor<S, InterpolatorMotion<S>>;

KERF_FOR_EACH_SCALAR(KERF_MOTION_INSTANCES)

}  // namespace kerf::motion
