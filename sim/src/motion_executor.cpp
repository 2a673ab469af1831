#include "kerf/sim/motion_executor.hpp"

namespace kerf::sim {

// core/motion (issue 4, branch issue-4-motion) has no interpolator on this
// branch yet. Rather than move the axes with something that is not kerf's
// interpolator, the board refuses to run; the adapter goes here once it is merged.
std::unique_ptr<SegmentExecutor> make_motion_executor(const MotionConfig&, std::string& why_not) {
  why_not = "the board has no motion executor: core/motion's interpolator (issue 4) is not merged";
  return nullptr;
}

}  // namespace kerf::sim
