// Member definitions of Interpolator<S> (included by interpolator.hpp).
#pragma once

namespace kerf::motion {

template <class S>
std::size_t Interpolator<S>::jerk_window_size(const MotionConfig<S>& c) {
  if (!(c.jerk > S(0)) || !(c.period > S(0))) return 1;
  const S n = S(2) * c.accel / (c.jerk * c.period);
  if (!(n < S(1e9))) return static_cast<std::size_t>(-1);  // no window can be that large
  const long whole = static_cast<long>(n);
  return static_cast<std::size_t>(Scalar<S>::from_int(whole) < n ? whole + 1 : max_of(whole, 1L));
}

template <class S>
Status Interpolator<S>::configure(const MotionConfig<S>& c) {
  using Sc = Scalar<S>;
  const bool finite = Sc::is_finite(c.period) && Sc::is_finite(c.accel) &&
                      Sc::is_finite(c.jerk) && Sc::is_finite(c.corner_angle) &&
                      Sc::is_finite(c.counts_per_mm.x) && Sc::is_finite(c.counts_per_mm.y);
  if (!finite || !(c.period > S(0)) || !(c.accel > S(0)) || c.jerk < S(0) ||
      c.corner_angle < S(0) || c.corner_angle > Sc::pi() || !(c.counts_per_mm.x > S(0)) ||
      !(c.counts_per_mm.y > S(0)))
    return Status::invalid_argument;
  const std::size_t n = jerk_window_size(c);
  if (n > 1 && n > window_.size()) return Status::capacity_exceeded;
  config_ = c;
  accel_step_ = c.accel * c.period * c.period;
  cos_corner_ = Sc::cos(c.corner_angle);
  snap_ = accel_step_ * S(1e-9);
  window_n_ = n;
  configured_ = true;
  reset();
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
  lead_ = 0;
  u_ = base_ = step_ = out_base_ = out_s_ = slow_until_ = S(0);
  plan_at_end_ = false;
  for (std::size_t i = 0; i < window_n_ && i < window_.size(); ++i) window_[i] = S(0);
  window_at_ = 0;
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
  plan_at_end_ = false;  // there is more path ahead of the plan now
  tail_end_ = p.geometry.end;
  tail_tangent_ = q.tangent_out;
  return Status::ok;
}

template <class S>
S Interpolator<S>::braking_distance() const {
  const S x = step_ - accel_step_;
  const S plan = x > S(0) ? braking_length(x, S(0), accel_step_) : S(0);
  return plan + (base_ + u_ - out_s_);  // the head also catches up with the plan
}

// The step for this period: as close to the target feed as the ramp allows,
// and no faster than every stop or slow point ahead allows (look-ahead).
template <class S>
S Interpolator<S>::plan_step() const {
  const S a = accel_step_;
  const S t = config_.period;
  const bool stopping = hold_ || abort_;
  const S target = stopping ? S(0) : queue_[lead_].path.feed * override_ * t;
  S x = min_of(target, step_ + a);
  if (base_ + u_ < slow_until_) x = min_of(x, slow_step_);  // just past a corner
  // No point further away than the braking length of x (plus the approach of
  // a point slower than x) can limit x.
  const S reach = braking_length(x, S(0), a) + (window_n_ > 1 ? approach(x) : S(0));
  const std::size_t n = queue_.size();
  S d = queue_[lead_].length - u_;
  for (std::size_t j = lead_; j < n && !(d > reach); ++j) {
    S w = S(0);  // the end of the queue is a stop
    if (j + 1 < n) {
      const QueuedSegment<S>& next = queue_[j + 1];
      w = min_of(next.corner_step, next.path.feed * override_ * t);
    }
    // A slow point (w > 0) must not be reached by a faster step either: a step
    // that ends exactly on a corner is followed by one that leaves it, and
    // both must keep to the corner speed. The end of the queue is reached
    // exactly.
    // With the S-curve, the head's step is the mean of the plan's last N
    // steps, so the plan keeps to w from (N + 1) w before the point.
    if (w < x) x = min_of(x, max_step_before(w > S(0) ? d - approach(w) : d, w, a));
    if (j + 1 < n) d = d + queue_[j + 1].length;
  }
  // Never brake harder than the limit (the plan above only guarantees it up to
  // rounding), never go backwards.
  return max_of(max_of(x, step_ - a), S(0));
}

// How far before a slow point (step limit w > 0) the plan keeps to w.
template <class S>
S Interpolator<S>::approach(S w) const {
  return window_n_ > 1 ? Scalar<S>::from_int(static_cast<long>(window_n_) + 1) * w : snap_;
}

// Moves the plan on by x along the queue.
template <class S>
void Interpolator<S>::advance_plan(S x) {
  const S before = base_ + u_;
  u_ = u_ + x;
  for (;;) {
    const QueuedSegment<S>& f = queue_[lead_];
    const bool last = lead_ + 1 == queue_.size();
    const S rest = f.length - u_;
    // a step that ends exactly on a joint stays on it: the next plan sees the joint
    if (last ? rest > snap_ : rest >= S(0)) break;
    if (last) {  // the end of the queue, reached exactly
      u_ = f.length;
      plan_at_end_ = true;
      break;
    }
    u_ = u_ - f.length;
    base_ = base_ + f.length;
    ++lead_;
    // The S-curve's head reaches the corner later: keep to the corner speed
    // for as long past it as before it.
    const S w = queue_[lead_].corner_step;
    if (window_n_ > 1 && w < Scalar<S>::infinity()) {
      slow_step_ = base_ < slow_until_ ? min_of(slow_step_, w) : w;
      slow_until_ = max_of(slow_until_, base_ + approach(w));
    }
  }
  step_ = plan_at_end_ ? base_ + u_ - before : x;
}

// The head's path length: the plan's, averaged over the S-curve window.
template <class S>
S Interpolator<S>::filtered(S s_plan) {
  if (window_n_ == 1) return s_plan;
  window_[window_at_] = s_plan;
  window_at_ = window_at_ + 1 == window_n_ ? 0 : window_at_ + 1;
  S sum = S(0);
  S low = s_plan;
  for (std::size_t i = 0; i < window_n_; ++i) {
    sum = sum + window_[i];
    low = min_of(low, window_[i]);
  }
  if (low == s_plan) return s_plan;  // settled: exactly the plan
  const S mean = sum / Scalar<S>::from_int(static_cast<long>(window_n_));
  return min_of(max_of(mean, out_s_), s_plan);  // rounding must not reverse or pass the plan
}

template <class S>
void Interpolator<S>::complete_front() {
  const QueuedSegment<S>& f = queue_.front();
  out_base_ = out_base_ + f.length;
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
  if (!plan_at_end_) advance_plan(plan_step());
  else step_ = S(0);
  const S s_plan = base_ + u_;
  const S s = filtered(s_plan);
  const S moved = s - out_s_;
  out_s_ = s;
  // The head leaves the segments behind it; the plan's segment stays.
  while (lead_ > 0 && !(out_s_ < out_base_ + queue_.front().length)) {
    complete_front();
    --lead_;
  }
  bool ended = false;
  const QueuedSegment<S>& f = queue_.front();
  last_.segment = front_index_;
  last_.sequence = f.path.sequence;
  if (plan_at_end_ && out_s_ == s_plan) {  // the head is at the end of the queue
    last_.position = f.path.geometry.end;
    complete_front();
    lead_ = 0;
    u_ = S(0);
    base_ = out_base_;
    plan_at_end_ = false;
    ended = true;
  } else {
    // on the plan's own segment and level with it, u_ is the exact offset
    const S local = lead_ == 0 && out_s_ == s_plan ? u_ : out_s_ - out_base_;
    last_.position = point_at(f, max_of(local, S(0)));
  }
  last_.s = out_s_;
  last_.speed = moved / config_.period;
  last_.counts = to_counts(last_.position, config_.counts_per_mm);
  const bool at_rest = !(step_ > S(0)) && !(moved > S(0)) && out_s_ == s_plan;
  if (abort_ && at_rest && !ended) {  // stopped on the path: drop the rest
    queue_.clear();
    lead_ = 0;
    u_ = S(0);
    base_ = out_base_ = out_s_;
    slow_until_ = S(0);
    tail_end_ = last_.position;
    ended = true;
  }
  if (ended) abort_ = hold_ = false;
  if (ended) last_.state = MotionState::done;
  else if (hold_ || abort_) last_.state = at_rest ? MotionState::held : MotionState::stopping;
  else last_.state = MotionState::running;
  return last_;
}

}  // namespace kerf::motion
