// The double instantiation of the motion code callers link against.
#include "kerf/motion/interpolator.hpp"

namespace kerf::motion {

template class PathQueue<double>;
template class Interpolator<double>;
template Result<QueuedSegment<double>> prepare_segment(const PathSegment<double>&);
template Vec2<double> point_at(const QueuedSegment<double>&, double);
template double braking_length(double, double, double);
template double max_step_before(double, double, double);
template double corner_step_limit(Vec2<double>, Vec2<double>, double, double);

}  // namespace kerf::motion
