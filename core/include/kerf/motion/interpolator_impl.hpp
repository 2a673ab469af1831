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
                      Sc::is_finite(c.counts_per_mm.x) && Sc::is_finite(c.counts_per_mm.y) &&
                      Sc::is_finite(c.vad) && !(c.vad < S(0)) && !(c.vad > S(1));
  if (!finite || !(c.period > S(0)) || !(c.accel > S(0)) || c.jerk < S(0) ||
      c.corner_angle < S(0) || c.corner_angle > Sc::pi() || !(c.counts_per_mm.x > S(0)) ||
      !(c.counts_per_mm.y > S(0)))
    return Status::invalid_argument;
  const std::size_t n = jerk_window_size(c);
  if (n > 1 && n > window_.size()) return Status::capacity_exceeded;
  config_ = c;
  accel_step_ = c.accel * c.period * c.period;
  jerk_step_ = c.jerk * c.period * c.period * c.period;
  rate_floor_ = tangential_step(accel_step_, accel_step_);
  // Some units of Fixed's resolution at least (1e-9 A is below it): a point
  // approach(w) before a joint must stay clear of the joint after rounding.
  snap_ = max_of(accel_step_ * S(1e-9), S(16) * Scalar<S>::epsilon());
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
  span_turn_ = span_kappa_ = spin_max_ = tail_kappa_ = S(0);
  depart_step_ = Scalar<S>::infinity();
  curved_count_ = curved_left_ = 0;
  rate_floor_ = tangential_step(accel_step_, accel_step_);
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
  const S a = accel_step_;
  const S b = jerk_step_;
  if (p.geometry.is_arc()) q.curvature = (p.geometry.dir > 0 ? S(1) : S(-1)) / q.radius;
  const S kappa = Scalar<S>::abs(q.curvature);
  q.cap_step = curve_step_cap(kappa, a, b);
  q.spin = kappa > S(0) ? q.cap_step * kappa : S(0);
  // An empty queue means the head is at rest: no joint to limit.
  q.turn = queue_.empty() ? S(0) : turn_chord(tail_tangent_, q.tangent_in);
  q.corner_step = queue_.empty() ? Scalar<S>::infinity()
                                 : joint_step_limit(q.turn, tail_kappa_, q.curvature, a, b);
  // Two chords span up to two steps: the turns of joints closer than that
  // behind this one add up (pieces shorter than a step).
  S turns = q.turn;
  S kappa_in = Scalar<S>::abs(tail_kappa_);
  S behind = S(0);
  for (std::size_t i = queue_.size(); i > 0 && q.corner_step < Scalar<S>::infinity(); --i) {
    const QueuedSegment<S>& e = queue_[i - 1];
    behind = behind + e.length;
    if (!(behind < S(2) * q.corner_step) || i == 1) break;  // the front's joint is behind the head
    turns = turns + e.turn;
    kappa_in = max_of(kappa_in, Scalar<S>::abs(queue_[i - 2].curvature));
    q.corner_step = min_of(q.corner_step, joint_step_limit(turns, kappa_in, q.curvature, a, b));
  }
  const Status s = queue_.push(q);
  if (s != Status::ok) return s;
  if (q.curved()) ++curved_count_;
  if (b > S(0) && q.spin > S(0)) {
    spin_max_ = max_of(spin_max_, q.spin);
    rate_floor_ = min_of(rate_floor_, b / (S(6) * q.spin));
  }
  tail_kappa_ = q.curvature;
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
  // the least rate wherever the queue turns or curves (see rate())
  const S r = curved_count_ > 0 || curved_left_ > 0 ? rate_floor_ : accel_step_;
  const S x = step_ - r;
  const S plan = x > S(0) ? braking_length(x, S(0), r) : S(0);
  return plan + (base_ + u_ - out_s_);  // the head also catches up with the plan
}

// The joints (their turns, summed) and the largest |curvature| within
// `ahead` of the plan, the plan's own segment included.
template <class S>
void Interpolator<S>::span_ahead(S ahead, S& turn, S& kappa) const {
  kappa = max_of(kappa, Scalar<S>::abs(queue_[lead_].curvature));
  S d = queue_[lead_].length - u_;
  for (std::size_t j = lead_ + 1; j < queue_.size() && !(d > ahead); ++j) {
    turn = turn + queue_[j].turn;
    kappa = max_of(kappa, Scalar<S>::abs(queue_[j].curvature));
    d = d + queue_[j].length;
  }
}

// How much the step may change by, around step x, where the chords span
// joints of total turn `turn` and curvature up to kappa (ramp/plane_limits.hpp).
// The S-curve's head lags the plan: while the queue holds (or the head may
// still be on) a turn or curvature, it is the least rate, held at once.
template <class S>
S Interpolator<S>::rate(S x, S turn, S kappa) const {
  const S a = accel_step_;
  if (window_n_ > 1) {
    if (curved_count_ == 0 && curved_left_ == 0) return a;
    S r = tangential_step(a, a);
    if (jerk_step_ > S(0) && spin_max_ > S(0)) r = min_of(r, jerk_step_ / (S(6) * spin_max_));
    return r;
  }
  if (!(turn > S(0)) && !(kappa > S(0))) return a;
  return tangential_step(x * (turn + x * kappa), a);
}

// The step for this period: as close to the target feed as the ramp allows,
// and no faster than every stop or slow point ahead allows (look-ahead).
template <class S>
S Interpolator<S>::plan_step() {
  const S a = accel_step_;
  const S t = config_.period;
  const bool stopping = hold_ || abort_;
  const QueuedSegment<S>& lead = queue_[lead_];
  const S target = stopping ? S(0) : min_of(lead.path.feed * override_ * t, lead.cap_step);
  // The normal part over the chords of the last step and the next.
  const S x_hi = max_of(step_, min_of(step_ + a, target));
  S turn_up = span_turn_;
  S kappa_up = span_kappa_;
  span_ahead(x_hi, turn_up, kappa_up);
  S x = min_of(target, step_ + rate(x_hi, turn_up, kappa_up));
  if (base_ + u_ < slow_until_) x = min_of(x, slow_step_);  // just past a joint
  // The chord of the last step spans the joints it crossed, so the pair of it
  // and this step turns there too: this step keeps to their corner cap as
  // well, else the normal part x (s + x kappa) outgrows the share k A that
  // rate() leaves it (the arrival alone is capped by the look-ahead below).
  x = min_of(x, depart_step_);
  // No point further away than the braking length of x (plus the approach of
  // a point slower than x) can limit x.
  const S reach = braking_length(x, S(0), rate_floor_) + approach(x);
  const std::size_t n = queue_.size();
  S d = queue_[lead_].length - u_;
  // what the braking runs over: the last step's joints, then the queue's
  S turn_run = span_turn_;
  S kappa_run = max_of(span_kappa_, Scalar<S>::abs(lead.curvature));
  for (std::size_t j = lead_; j < n && !(d > reach); ++j) {
    S w = S(0);  // the end of the queue is a stop
    if (j + 1 < n) {
      const QueuedSegment<S>& next = queue_[j + 1];
      w = min_of(min_of(next.corner_step, next.cap_step), next.path.feed * override_ * t);
    }
    // A slow point (w > 0) must not be reached by a faster step either: the
    // plan keeps to w from approach(w) before it, so that the steps on both
    // sides of the point do. The end of the queue is reached exactly.
    if (w < x) {
      // The end of the queue may turn into a joint of any turn when the
      // sender pushes more: braking there leaves the normal part its share.
      const S r = j + 1 < n ? rate(x, turn_run, kappa_run) : min_of(rate_floor_, rate(x, turn_run, kappa_run));
      x = min_of(x, max_step_before(w > S(0) ? d - approach(w) : d, w, r));
    }
    if (j + 1 < n) {
      turn_run = max_of(turn_run, queue_[j + 1].turn);
      kappa_run = max_of(kappa_run, Scalar<S>::abs(queue_[j + 1].curvature));
      d = d + queue_[j + 1].length;
    }
  }
  // Never brake harder than the limit (the plan above only guarantees it up to
  // rounding), never go backwards.
  S turn_dn = span_turn_;
  S kappa_dn = span_kappa_;
  span_ahead(max_of(x, step_ - a), turn_dn, kappa_dn);
  return max_of(max_of(x, step_ - rate(step_, turn_dn, kappa_dn)), S(0));
}

// How far before a slow point (step limit w > 0) the plan keeps to w.
template <class S>
S Interpolator<S>::approach(S w) const {
  return window_n_ > 1 ? Scalar<S>::from_int(static_cast<long>(window_n_) + 1) * w : w + snap_;
}

// Moves the plan on by x along the queue.
template <class S>
void Interpolator<S>::advance_plan(S x) {
  const S before = base_ + u_;
  u_ = u_ + x;
  span_turn_ = S(0);
  span_kappa_ = Scalar<S>::abs(queue_[lead_].curvature);
  depart_step_ = Scalar<S>::infinity();
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
    span_turn_ = span_turn_ + queue_[lead_].turn;
    span_kappa_ = max_of(span_kappa_, Scalar<S>::abs(queue_[lead_].curvature));
    // a step that started on the joint has no turn within its chord
    if (base_ > before) depart_step_ = min_of(depart_step_, queue_[lead_].corner_step);
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
  if (f.curved()) {
    --curved_count_;
    curved_left_ = window_n_ + 3;  // the head's last chords on it are still averaged in
  }
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
    last_.thc_lock = true;
    if (last_.state != MotionState::idle) last_.state = MotionState::done;
    abort_ = false;
    return last_;
  }
  if (curved_left_ > 0) --curved_left_;
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
  const S cut_feed = f.path.feed * override_;  // (f is popped if the head ends here)
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
  last_.thc_lock = last_.speed < config_.vad * cut_feed;
  last_.counts = to_counts(last_.position, config_.counts_per_mm);
  const bool at_rest = !(step_ > S(0)) && !(moved > S(0)) && out_s_ == s_plan;
  if (abort_ && at_rest && !ended) {  // stopped on the path: drop the rest
    queue_.clear();
    curved_count_ = 0;
    lead_ = 0;
    u_ = S(0);
    base_ = out_base_ = out_s_;
    slow_until_ = S(0);
    tail_end_ = last_.position;
    ended = true;
  }
  if (ended) {  // at rest: a segment pushed now starts from rest, with no joint behind it
    abort_ = hold_ = false;
    step_ = span_turn_ = span_kappa_ = S(0);
    depart_step_ = Scalar<S>::infinity();
  }
  if (ended) last_.state = MotionState::done;
  else if (hold_ || abort_) last_.state = at_rest ? MotionState::held : MotionState::stopping;
  else last_.state = MotionState::running;
  return last_;
}

}  // namespace kerf::motion
