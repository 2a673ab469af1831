// The fixed-point (kerf::Fixed) instantiation of the motion code callers link against.
#include "kerf/core/fixed.hpp"
#include "kerf/motion/interpolator.hpp"

namespace kerf::motion {

template class PathQueue<Fixed>;
template class Interpolator<Fixed>;
template Result<QueuedSegment<Fixed>> prepare_segment(const PathSegment<Fixed>&);
template Vec2<Fixed> point_at(const QueuedSegment<Fixed>&, Fixed);
template Fixed braking_length(Fixed, Fixed, Fixed);
template Fixed max_step_before(Fixed, Fixed, Fixed);
template Fixed corner_step_limit(Vec2<Fixed>, Vec2<Fixed>, Fixed, Fixed);

}  // namespace kerf::motion
