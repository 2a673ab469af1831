#include "kerf/sim/motion_executor.hpp"

#include <vector>

#include "kerf/motion/interpolator_motion.hpp"

namespace kerf::sim {

namespace {

// core/motion's interpolator stage behind the board's SegmentExecutor
// interface (the stage itself is motion::InterpolatorMotion).
class InterpolatorExecutor final : public SegmentExecutor {
 public:
  explicit InterpolatorExecutor(const MotionConfig& cfg)
      : storage_(cfg.lookahead_slots),
        window_(64),  // S-curve averaging window; the board runs trapezoidal ramps (jerk 0)
        motion_({storage_.data(), storage_.size()}, {window_.data(), window_.size()}),
        cfg_(cfg) {}

  bool configure(std::string& why_not) {
    motion::MotionConfig<double> mc;
    mc.period = cfg_.servo_period_s;
    mc.accel = cfg_.accel_mm_s2;
    mc.jerk = 0.0;
    mc.corner_angle = cfg_.corner_angle_rad;
    mc.vad = cfg_.vad;
    mc.counts_per_mm = {cfg_.counts_per_mm, cfg_.counts_per_mm};
    if (motion_.configure(mc) != Status::ok) {
      why_not = "the motion configuration is out of range";
      return false;
    }
    return true;
  }

  std::size_t free_slots() const override { return motion_.free_slots(); }
  bool push(Vec2<double> from, const hal::SegmentCommand& seg) override { return motion_.push(from, seg); }
  ExecStep step() override { return motion_.step(); }
  void hold() override { motion_.hold(); }
  void resume() override { motion_.resume(); }
  void abort() override { motion_.abort(); }
  void reset(Vec2<double> at) override { motion_.reset(at); }

 private:
  std::vector<motion::QueuedSegment<double>> storage_;
  std::vector<double> window_;
  motion::InterpolatorMotion<double> motion_;
  MotionConfig cfg_;
};

}  // namespace

std::unique_ptr<SegmentExecutor> make_motion_executor(const MotionConfig& cfg, std::string& why_not) {
  if (cfg.lookahead_slots < 1) {
    why_not = "the interpolator needs at least one queue slot";
    return nullptr;
  }
  auto e = std::make_unique<InterpolatorExecutor>(cfg);
  if (!e->configure(why_not)) return nullptr;
  return e;
}

}  // namespace kerf::sim
