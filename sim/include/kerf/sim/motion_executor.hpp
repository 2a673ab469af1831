// The board's real executor: core/motion's constant-feed interpolator behind
// sim::SegmentExecutor. This is the one file that binds the board to core/motion.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "kerf/sim/segment_executor.hpp"

namespace kerf::sim {

struct MotionConfig {
  double servo_period_s = 0.001;
  double accel_mm_s2 = 2000.0;     // along the path
  double corner_angle_rad = 0.05;  // tangent turns above this are corners
  double vad = 0.9;                // thc_lock below this fraction of the cut feed ([cut] vad / 100)
  double counts_per_mm = 1000.0;   // the drives' resolution (1 count = 1 um, as on the wire)
  std::size_t lookahead_slots = 16;
};

// Null, with the reason in `why_not`, when the configuration is refused.
std::unique_ptr<SegmentExecutor> make_motion_executor(const MotionConfig& cfg, std::string& why_not);

}  // namespace kerf::sim
