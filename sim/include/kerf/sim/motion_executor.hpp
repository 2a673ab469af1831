// The board's real executor: core/motion's constant-feed interpolator
// behind sim::SegmentExecutor. This is the one place that binds the board to
// core/motion (issue 4).
#pragma once

#include <memory>
#include <string>

#include "kerf/sim/segment_executor.hpp"

namespace kerf::sim {

struct MotionConfig {
  double servo_period_s = 0.001;
  double counts_per_mm = 1000.0;  // the drive's resolution
};

// Null, with the reason in `why_not`, when no interpolator is built in.
std::unique_ptr<SegmentExecutor> make_motion_executor(const MotionConfig& cfg, std::string& why_not);

}  // namespace kerf::sim
