// BoardExecutor's definitions (included by board_executor.hpp).
#pragma once

#include "kerf/core/assert.hpp"

namespace kerf::motion {

template <class S, class Motion>
BoardExecutor<S, Motion>::BoardExecutor(Motion& motion, Span<BoardSegment<S>> queue, Vec2<S> start)
    : motion_(motion), queue_(queue), position_(start), tail_end_(start) {
  KERF_ASSERT(queue.size() > 0);
  KERF_ASSERT(queue.size() + motion.free_slots() < kTorchWindow);
  motion_.reset(start);
}

template <class S, class Motion>
BoardAccept BoardExecutor<S, Motion>::accept(const BoardSegment<S>& seg) {
  if (seg.seq <= last_accepted_) {
    ++duplicates_;
    return BoardAccept::duplicate;
  }
  if (seg.seq != last_accepted_ + 1) return BoardAccept::gap;
  if (state_ == BoardState::fault || state_ == BoardState::done || finish_) return BoardAccept::invalid;
  if (count_ == queue_.size()) return BoardAccept::full;
  std::size_t at = head_ + count_;
  if (at >= queue_.size()) at -= queue_.size();
  queue_[at] = seg;
  ++count_;
  last_accepted_ = seg.seq;
  return BoardAccept::queued;
}

template <class S, class Motion>
bool BoardExecutor<S, Motion>::command(BoardCommand c) {
  switch (c) {
    case BoardCommand::start:  // from idle, or after a finished run: a new run
      if (state_ != BoardState::idle && state_ != BoardState::done) return false;
      state_ = BoardState::running;
      finish_ = false;
      return true;
    case BoardCommand::hold:
      if (state_ != BoardState::running) return false;
      state_ = BoardState::hold;
      motion_.hold();
      z_.hold();
      return true;
    case BoardCommand::resume:
      if (state_ != BoardState::hold) return false;
      state_ = BoardState::running;
      motion_.resume();
      z_.resume();
      moving_ = true;  // step again even if the queue waits on the host
      return true;
    case BoardCommand::abort: fault(kBoardFaultAbort); return true;
    case BoardCommand::fault_reset:
      // Latched until the fault reaction is over, as a drive does: a reset
      // at once would leave the brake unfinished and start the next segment
      // from a point the axes have not reached.
      if (state_ != BoardState::fault) return false;
      reset_pending_ = true;
      if (!busy_) reset_now(position_);
      return true;
    case BoardCommand::finish: finish_ = true; return true;
  }
  return false;
}

template <class S, class Motion>
void BoardExecutor<S, Motion>::fault(std::uint16_t bits) {
  torch_ = false;
  state_ = BoardState::fault;
  faults_ = static_cast<std::uint16_t>(faults_ | bits);
  reset_pending_ = false;  // a fault after the reset command wants a reset of its own
  executing_ = 0;
  count_ = 0;
  motion_.abort();
  z_.abort();
}

template <class S, class Motion>
void BoardExecutor<S, Motion>::reset(Vec2<S> at) {
  if (state_ == BoardState::fault) reset_now(at);
}

template <class S, class Motion>
void BoardExecutor<S, Motion>::reset_now(Vec2<S> at) {
  state_ = BoardState::idle;
  faults_ = 0;
  reset_pending_ = false;
  finish_ = false;
  busy_ = moving_ = false;
  executing_ = 0;
  torch_ = false;
  position_ = tail_end_ = at;         // the next segment starts where the axes stopped
  dropped_through_ = last_accepted_;  // what the fault dropped never ran
  motion_.reset(at);
  z_.reset(z_.position());
}

template <class S, class Motion>
void BoardExecutor<S, Motion>::hand_over() {
  while (count_ > 0 && motion_.free_slots() > 0 && !z_.busy()) {
    const BoardSegment<S>& seg = queue_[head_];
    if (seg.z_move) {
      if (busy_) return;  // after the segments before it, at rest
      if (!start_z(seg)) {
        fault(kBoardFaultBadSegment);
        return;
      }
    } else if (!limits_.contains(segment_extent(tail_end_, seg))) {
      fault(kBoardFaultSoftLimit);
      return;
    } else if (!motion_.push(tail_end_, seg)) {
      fault(kBoardFaultBadSegment);
      return;
    } else {
      tail_end_ = seg.end;
    }
    set_torch_of(seg.seq, seg.torch);
    busy_ = true;
    head_ = head_ + 1 == queue_.size() ? 0 : head_ + 1;
    --count_;
  }
}

template <class S, class Motion>
bool BoardExecutor<S, Motion>::start_z(const BoardSegment<S>& seg) {
  const S tol = S(kZXyTolerance);
  if (Scalar<S>::abs(seg.end.x - tail_end_.x) > tol || Scalar<S>::abs(seg.end.y - tail_end_.y) > tol) return false;
  return z_.start(seg.z, seg.feed, seg.seq);
}

template <class S, class Motion>
BoardStep<S> BoardExecutor<S, Motion>::step(bool wait_for_drives) {
  BoardStep<S> out;
  const std::uint32_t from = last_executed_ > dropped_through_ ? last_executed_ : dropped_through_;
  out.completed_from = out.completed_to = from;
  if (active() || state_ == BoardState::fault) {
    if (state_ == BoardState::running) hand_over();
    const MotionStep<S> e = motion_.step();
    const std::uint32_t z_running = z_.running();
    const std::uint32_t z_done = z_.step();
    out.stepped = true;
    position_ = e.position;
    busy_ = !e.at_rest || z_.busy();
    moving_ = e.moving || z_.moving();
    thc_lock_ = e.thc_lock || z_running != 0;
    // Sequence numbers are consecutive (only last + 1 is queued), so every
    // number up to last_completed ran, except those a fault dropped. A z
    // move runs alone, after every segment before it.
    const std::uint32_t completed = e.last_completed > z_done ? e.last_completed : z_done;
    if (completed > from) out.completed_to = completed;
    if (completed > last_executed_) last_executed_ = completed;
    if (state_ != BoardState::fault) {
      executing_ = e.running != 0 ? e.running : z_.running();
      torch_ = executing_ != 0 && torch_of(executing_);
    }
    if (state_ == BoardState::fault && reset_pending_ && !busy_) reset_now(position_);
    if (!wait_for_drives) finish_if_done();
  }
  out.position = position_;
  out.z = z_.position();
  out.executing = executing_;
  out.torch = torch_;
  out.thc_lock = thc_lock_;
  return out;
}

template <class S, class Motion>
void BoardExecutor<S, Motion>::finish_if_done() {
  if (state_ == BoardState::running && finish_ && count_ == 0 && !busy_) {
    state_ = BoardState::done;
    torch_ = false;
  }
}

template <class S, class Motion>
bool BoardExecutor<S, Motion>::needs_step(bool paced) const {
  switch (state_) {
    case BoardState::fault: return busy_ || reset_pending_;  // still braking
    case BoardState::hold: return moving_;  // braking; at rest it waits for resume
    case BoardState::running: return count_ > 0 || finish_ || (paced && busy_);
    default: return false;
  }
}

template <class S, class Motion>
bool BoardExecutor<S, Motion>::torch_of(std::uint32_t seq) const {
  const std::uint32_t bit = seq % kTorchWindow;
  return ((torch_bits_[bit / 32] >> (bit % 32)) & 1u) != 0;
}

template <class S, class Motion>
void BoardExecutor<S, Motion>::set_torch_of(std::uint32_t seq, bool on) {
  const std::uint32_t bit = seq % kTorchWindow;
  const std::uint32_t mask = 1u << (bit % 32);
  torch_bits_[bit / 32] = on ? (torch_bits_[bit / 32] | mask) : (torch_bits_[bit / 32] & ~mask);
}

}  // namespace kerf::motion
