// Member definitions of Interpolator<S> (included by interpolator.hpp).
#pragma once

namespace kerf::motion {

template <class S>
Status Interpolator<S>::configure(const MotionConfig<S>& c) {
  using Sc = Scalar<S>;
  const bool finite = Sc::is_finite(c.period) && Sc::is_finite(c.accel) &&
                      Sc::is_finite(c.jerk) && Sc::is_finite(c.corner_angle) &&
                      Sc::is_finite(c.counts_per_mm.x) && Sc::is_finite(c.counts_per_mm.y);
  if (!finite || !(c.period > S(0)) || !(c.accel > S(0)) || !(c.jerk == S(0)) ||
      c.corner_angle < S(0) || c.corner_angle > Sc::pi() || !(c.counts_per_mm.x > S(0)) ||
      !(c.counts_per_mm.y > S(0)))
    return Status::invalid_argument;
  config_ = c;
  accel_step_ = c.accel * c.period * c.period;
  cos_corner_ = Sc::cos(c.corner_angle);
  snap_ = accel_step_ * S(1e-9);
  configured_ = true;
  return Status::ok;
}

template <class S>
Status Interpolator<S>::set_override(S percent) {
  if (!(percent >= S(10)) || !(percent <= S(200))) return Status::invalid_argument;
  override_ = percent / S(100);
  return Status::ok;
}

template <class S>
void Interpolator<S>::reset() {
  queue_.clear();
  hold_ = abort_ = false;
  u_ = base_ = step_ = S(0);
  has_position_ = false;
  front_index_ = completed_ = 0;
  last_completed_sequence_ = 0;
  last_ = Setpoint<S>{};
}

template <class S>
Status Interpolator<S>::push(const PathSegment<S>& p) {
  KERF_ASSERT(configured_);
  if (queue_.full()) return Status::capacity_exceeded;
  Result<QueuedSegment<S>> r = prepare_segment(p);
  if (!r.ok()) return r.status();
  QueuedSegment<S>& q = r.value();
  const Vec2<S> start = p.geometry.start;
  if (has_position_) {
    const Vec2<S> gap = start - tail_end_;
    const S scale = S(1) + max_of(Scalar<S>::abs(tail_end_.x), Scalar<S>::abs(tail_end_.y));
    if (max_of(Scalar<S>::abs(gap.x), Scalar<S>::abs(gap.y)) > scale * S(1e-9))
      return Status::invalid_argument;
  }
  // An empty queue means the head is at rest: no joint to limit.
  q.corner_step = queue_.empty()
                      ? Scalar<S>::infinity()
                      : corner_step_limit(tail_tangent_, q.tangent_in, cos_corner_, accel_step_);
  const Status s = queue_.push(q);
  if (s != Status::ok) return s;
  if (!has_position_) {
    has_position_ = true;
    last_.position = start;
    last_.counts = to_counts(start, config_.counts_per_mm);
    last_.segment = front_index_;
    last_.sequence = p.sequence;
  }
  tail_end_ = p.geometry.end;
  tail_tangent_ = q.tangent_out;
  return Status::ok;
}

template <class S>
S Interpolator<S>::braking_distance() const {
  const S x = step_ - accel_step_;
  return x > S(0) ? braking_length(x, S(0), accel_step_) : S(0);
}

// The step for this period: as close to the target feed as the ramp allows,
// and no faster than every stop or slow point ahead allows (look-ahead).
template <class S>
S Interpolator<S>::plan_step() const {
  const S a = accel_step_;
  const S t = config_.period;
  const bool stopping = hold_ || abort_;
  const S target = stopping ? S(0) : queue_.front().path.feed * override_ * t;
  S x = min_of(target, step_ + a);
  // No point further away than the braking length of x can limit x.
  const S reach = braking_length(x, S(0), a);
  const std::size_t n = queue_.size();
  S d = queue_.front().length - u_;
  for (std::size_t j = 0; j < n && !(d > reach); ++j) {
    S w = S(0);  // the end of the queue is a stop
    if (j + 1 < n) {
      const QueuedSegment<S>& next = queue_[j + 1];
      w = min_of(next.corner_step, next.path.feed * override_ * t);
    }
    if (w < x) x = min_of(x, max_step_before(d, w, a));
    if (j + 1 < n) d = d + queue_[j + 1].length;
  }
  // Never brake harder than the limit (the plan above only guarantees it up to
  // rounding), never go backwards.
  return max_of(max_of(x, step_ - a), S(0));
}

template <class S>
void Interpolator<S>::complete_front() {
  const QueuedSegment<S>& f = queue_.front();
  base_ = base_ + f.length;
  ++completed_;
  last_completed_sequence_ = f.path.sequence;
  queue_.pop_front();
  ++front_index_;
}

template <class S>
Setpoint<S> Interpolator<S>::step() {
  KERF_ASSERT(configured_);
  if (queue_.empty()) {
    step_ = S(0);
    last_.speed = S(0);
    if (last_.state != MotionState::idle) last_.state = MotionState::done;
    abort_ = false;
    return last_;
  }
  const S before = base_ + u_;
  S x = plan_step();
  u_ = u_ + x;
  bool ended = false;
  for (;;) {
    const QueuedSegment<S>& f = queue_.front();
    const bool last = queue_.size() == 1;
    const S rest = f.length - u_;
    if (last ? rest > snap_ : rest > S(0)) break;
    if (last) {
      last_.position = f.path.geometry.end;
      last_.segment = front_index_;
      last_.sequence = f.path.sequence;
      u_ = S(0);
      complete_front();
      ended = true;
      break;
    }
    u_ = u_ - f.length;
    complete_front();
  }
  if (!ended) {
    const QueuedSegment<S>& f = queue_.front();
    last_.position = point_at(f, u_);
    last_.segment = front_index_;
    last_.sequence = f.path.sequence;
  }
  const S now = base_ + u_;
  step_ = ended ? now - before : x;
  last_.s = now;
  last_.speed = step_ / config_.period;
  last_.counts = to_counts(last_.position, config_.counts_per_mm);
  const bool at_rest = !(step_ > S(0));
  if (abort_ && at_rest) {  // stopped on the path: drop the rest
    queue_.clear();
    base_ = now;
    u_ = S(0);
    tail_end_ = last_.position;
    abort_ = hold_ = false;
    ended = true;
  }
  if (ended) last_.state = MotionState::done;
  else if (hold_ || abort_) last_.state = at_rest ? MotionState::held : MotionState::stopping;
  else last_.state = MotionState::running;
  return last_;
}

}  // namespace kerf::motion
