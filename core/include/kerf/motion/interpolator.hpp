// The constant-feed interpolator. A sender (the CLI, a motion board, a drive
// simulator) pushes segments; each servo period it calls step() and gets one
// setpoint: the exact position, the drive counts, the path length travelled.
//
// Motion rules:
// - Each period advances feed * override * period along the path. What is left
//   of a step at a joint carries into the next segment, so the speed does not
//   dip at joints.
// - Ramps are trapezoidal: the step changes by at most A = accel * period^2
//   per period along the path on a straight path, and by what the plane
//   limit leaves elsewhere (below). They happen only at the start, at the
//   end of the queue, on feed hold / abort, where the feed, the override or
//   a speed cap drops, and at joints.
// - The plane limit (ramp/plane_limits.hpp): the velocity vector changes by
//   at most accel * period per period, tangential and normal parts together.
//   Each arc caps the speed (v^2 / r <= 0.85 accel); each joint caps it from
//   its turn and the curvatures on both sides (the corner rule: v (2
//   sin(theta / 2) + v T kappa) <= 0.85 accel T); the step changes by at
//   most sqrt(A^2 - c^2), c being the normal part over the period, computed
//   from the joints and the curvature the period's chords span. The plan
//   keeps to a joint's speed from one step before it, so the steps on both
//   sides of it do, and for the step after one that crossed it (that
//   step's chord turns at the joint: the pair's normal part is x s too).
// - S-curve (jerk > 0): the trapezoidal path length s(t) is averaged over the
//   last N = ceil(2 accel / (jerk period)) periods. A moving average of a
//   profile whose step changes by at most A keeps that bound and changes the
//   acceleration by at most 2A / N per period, i.e. the jerk limit. The head
//   lags the trapezoidal plan by (N - 1) / 2 periods; it still never passes
//   the plan, so the end, holds and aborts stay exact. So that the head
//   keeps to a slow point's speed (a joint, a lower feed), the plan does so
//   from (N + 1) steps before it, and at joints as far past it too. The
//   normal part of the jerk is bounded by speed: at a curvature step
//   v^2 |d kappa| <= jerk T / 2 (a tangent jump has no bounded jerk), on
//   an arc v^3 kappa^2 <= jerk / 2, and while the queue holds any turn or
//   curvature the tangential step change is the plane limit's least,
//   sqrt(1 - 0.85^2) A (and at most jerk T^3 / (6 x kappa) on arcs).
// - corner_angle no longer changes the limits (every turn is limited by the
//   plane rule); it is still checked, so configurations that set it stay valid.
// - Look-ahead runs over the whole queue (until the braking distance is
//   covered), so the end ramp starts in time even when the last segments are
//   shorter than the braking distance. The end of the queue is a stop: if the
//   sender does not keep the queue full, the head stops there, exactly.
// - The path is never overshot and never run backwards.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kerf/core/span.hpp"
#include "kerf/core/status.hpp"
#include "kerf/motion/counts.hpp"
#include "kerf/motion/path_geometry.hpp"
#include "kerf/motion/path_queue.hpp"
#include "kerf/motion/ramp/lookahead.hpp"
#include "kerf/motion/ramp/plane_limits.hpp"

namespace kerf::motion {

enum class MotionState : std::uint8_t {
  idle,      // nothing queued yet (or after reset)
  running,   // moving, or about to
  stopping,  // feed hold or abort: braking on the path
  held,      // feed hold: at rest on the path; resume() continues
  done,      // the queue ran out (or an abort finished): at rest
};

template <class S>
struct MotionConfig {
  S period{};                         // servo period T, s (> 0)
  S accel{};                          // acceleration limit in the plane, mm/s^2 (> 0)
  S jerk{};                           // mm/s^3; 0: trapezoidal, > 0: S-curve (needs a window)
  S corner_angle{};                   // rad in [0, pi]; no longer used by the limits
  // Torch-height control locks (Setpoint::thc_lock) while the speed is below
  // this fraction of the segment's feed (times the override): velocity anti-dive.
  S vad = S(0.9);                     // in [0, 1]
  Vec2<S> counts_per_mm{S(1), S(1)};  // per axis (> 0)
};

template <class S>
struct Setpoint {
  Vec2<S> position{};          // exact commanded position, mm
  Counts counts{};             // what the drives receive
  S s{};                       // path length travelled since reset, mm
  S speed{};                   // along the path over the last period, mm/s
  std::uint64_t segment = 0;   // index of the segment (0 = first pushed since reset)
  std::uint32_t sequence = 0;  // that segment's sequence number
  MotionState state = MotionState::idle;
  bool thc_lock = true;        // speed below vad of the cut feed: hold the torch height
};

template <class S>
class Interpolator {
 public:
  // storage: the queue's slots; its size is the queue capacity (>= 1).
  // jerk_window: room for the S-curve's moving average, jerk_window_size(c)
  // values; not needed for trapezoidal ramps.
  explicit Interpolator(Span<QueuedSegment<S>> storage, Span<S> jerk_window = {})
      : queue_(storage), window_(jerk_window) {
    KERF_ASSERT(storage.size() > 0);
  }

  // The window an S-curve with these limits needs (1 when jerk is 0).
  static std::size_t jerk_window_size(const MotionConfig<S>& c);

  // Sets the limits and resets (see reset()); must be called before push()
  // and step(). invalid_argument (and nothing changed) for a limit out of
  // range; capacity_exceeded when the jerk window is smaller than
  // jerk_window_size(c).
  Status configure(const MotionConfig<S>& c);

  // Appends a segment. capacity_exceeded when the queue is full,
  // invalid_argument for a bad feed or geometry (see prepare_segment) or when
  // it does not start where the previous segment ended. Nothing is changed then.
  Status push(const PathSegment<S>& p);

  // Advances one servo period and returns the setpoint.
  Setpoint<S> step();

  void hold() { hold_ = true; }  // brake to a stop on the path, then wait
  void resume() { hold_ = false; }
  void abort() { abort_ = true; }  // brake to a stop on the path, then drop the queue
  // Feed override in percent, 10..200 (invalid_argument otherwise). Speed
  // changes to it are ramped like any other.
  Status set_override(S percent);
  S override_percent() const { return override_ * S(100); }

  // Back to idle at no position, the queue empty; the configuration is kept.
  void reset();

  MotionState state() const { return last_.state; }
  const Setpoint<S>& last_setpoint() const { return last_; }
  std::size_t queued() const { return queue_.size(); }
  std::size_t capacity() const { return queue_.capacity(); }
  std::size_t free_slots() const { return queue_.capacity() - queue_.size(); }
  // Segments finished since reset, and the sequence number of the last one.
  std::uint64_t completed_count() const { return completed_; }
  bool has_completed() const { return completed_ > 0; }
  std::uint32_t last_completed_sequence() const { return last_completed_sequence_; }
  // How much further the head travels if hold() is called now, mm.
  S braking_distance() const;

 private:
  S plan_step();
  void span_ahead(S ahead, S& turn, S& kappa) const;
  S rate(S x, S turn, S kappa) const;
  void advance_plan(S x);
  S filtered(S s_plan);
  S approach(S w) const;
  void complete_front();

  PathQueue<S> queue_;
  MotionConfig<S> config_{};
  bool configured_ = false;
  S accel_step_{};  // A = accel * period^2
  S jerk_step_{};   // B = jerk * period^3 (0: no jerk limit)
  S rate_floor_{};  // the least the step may change by anywhere
  S snap_{};        // an end closer than this is reached
  S override_ = S(1);
  bool hold_ = false;
  bool abort_ = false;
  // The trapezoidal plan runs ahead on segment lead_ (the head may still be
  // on an earlier one, with the S-curve's lag).
  std::size_t lead_ = 0;
  S u_{};          // distance into segment lead_
  S base_{};       // path length at its start
  S step_{};       // the plan's last step, mm per period
  bool plan_at_end_ = false;  // the plan has reached the end of the queue
  S slow_until_{};            // the plan keeps to slow_step_ until here (S-curve corners)
  S slow_step_{};
  S span_turn_{};   // turns of the joints the plan's last step crossed
  S span_kappa_{};  // and the largest |curvature| it ran on
  S depart_step_{};  // the least corner_step of those joints: the next step's cap too
  std::size_t curved_count_ = 0;  // queued segments with a turn or curvature
  std::size_t curved_left_ = 0;   // S-curve: periods the head may still feel one
  S spin_max_{};                  // the largest spin pushed since reset
  S tail_kappa_{};                // curvature of the last pushed segment
  S out_base_{};   // path length at the front segment's start
  S out_s_{};      // the head's path length
  Span<S> window_{};
  std::size_t window_n_ = 1;
  std::size_t window_at_ = 0;
  bool has_position_ = false;
  Vec2<S> tail_end_{};      // where the last pushed segment ends
  Vec2<S> tail_tangent_{};  // and its direction there
  std::uint64_t front_index_ = 0;
  std::uint64_t completed_ = 0;
  std::uint32_t last_completed_sequence_ = 0;
  Setpoint<S> last_{};
};

}  // namespace kerf::motion

#include "kerf/motion/interpolator_impl.hpp"
