#include "kerf/sim/motion_executor.hpp"

#include <vector>

#include "kerf/motion/interpolator.hpp"

namespace kerf::sim {

namespace {

// core/motion's constant-feed interpolator as the board's executor. The
// drives receive integer counts, so the position reported (and traced) is
// the counts converted back to mm: what the axes actually do.
class InterpolatorExecutor final : public SegmentExecutor {
 public:
  explicit InterpolatorExecutor(const MotionConfig& cfg)
      : storage_(cfg.lookahead_slots),
        window_(64),  // S-curve averaging window; the board runs trapezoidal ramps (jerk 0)
        interp_({storage_.data(), storage_.size()}, {window_.data(), window_.size()}),
        cfg_(cfg) {}

  bool configure(std::string& why_not) {
    motion::MotionConfig<double> mc;
    mc.period = cfg_.servo_period_s;
    mc.accel = cfg_.accel_mm_s2;
    mc.jerk = 0.0;
    mc.corner_angle = cfg_.corner_angle_rad;
    mc.counts_per_mm = {cfg_.counts_per_mm, cfg_.counts_per_mm};
    if (interp_.configure(mc) != Status::ok) {
      why_not = "the motion configuration is out of range";
      return false;
    }
    return true;
  }

  std::size_t free_slots() const override { return interp_.free_slots(); }

  bool push(Vec2<double> from, const hal::SegmentCommand& seg) override {
    // The board knows its position in counts; the interpolator stopped at an
    // exact point of the path (after a hold or an abort). A new run starts
    // there when the two agree to within a count, so that the joint is exact.
    if (interp_.queued() == 0 && have_exact_ &&
        distance(from, exact_) <= 1.5 / cfg_.counts_per_mm)
      from = exact_;
    motion::PathSegment<double> p;
    p.geometry = seg.kind == SegmentKind::arc ? Segment<double>::arc(from, seg.end, seg.centre, seg.dir)
                                              : Segment<double>::line(from, seg.end);
    p.feed = seg.feed;
    p.sequence = seg.seq;
    return interp_.push(p) == Status::ok;
  }

  ExecStep step() override {
    const motion::Setpoint<double> sp = interp_.step();
    exact_ = sp.position;
    have_exact_ = true;
    ExecStep e;
    e.position = {static_cast<double>(sp.counts.x) / cfg_.counts_per_mm,
                  static_cast<double>(sp.counts.y) / cfg_.counts_per_mm};
    e.last_completed = interp_.last_completed_sequence();
    const bool moving = sp.state == motion::MotionState::running ||
                        sp.state == motion::MotionState::stopping;
    e.running = moving && interp_.queued() > 0 ? sp.sequence : 0;
    e.moving = sp.speed > 0.0;
    e.at_rest = !moving && interp_.queued() == 0;
    return e;
  }
  void hold() override { interp_.hold(); }
  void resume() override { interp_.resume(); }
  void abort() override { interp_.abort(); }

 private:
  std::vector<motion::QueuedSegment<double>> storage_;
  std::vector<double> window_;
  motion::Interpolator<double> interp_;
  MotionConfig cfg_;
  Vec2<double> exact_{};  // where the interpolator is, exactly (not rounded to counts)
  bool have_exact_ = false;
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
