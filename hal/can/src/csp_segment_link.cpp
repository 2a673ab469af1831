#include "kerf/hal/can/csp_segment_link.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

namespace kerf::hal {

namespace {

std::uint16_t fault_bit(AxisError e) {
  switch (e) {
    case AxisError::heartbeat_lost: return kFaultHeartbeat;
    case AxisError::emcy: return kFaultEmcy;
    case AxisError::bus_off: return kFaultBusOff;
    case AxisError::send_failed: return kFaultSend;
    default: return kFaultDrive;
  }
}

constexpr double kMaxCounts = 2147483647.0;  // 0x607A is a signed 32-bit value

}  // namespace

std::unique_ptr<CspSegmentLink> CspSegmentLink::create(AxisLink& axes, const CspConfig& cfg,
                                                       std::string& error) {
  if (axes.axis_count() < 2) {
    error = "CSP link: needs at least two axes (x and y)";
    return nullptr;
  }
  if (cfg.queue_slots < 1 || cfg.queue_slots > 200) {
    error = "CSP link: queue slots must be 1..200";
    return nullptr;
  }
  std::unique_ptr<CspSegmentLink> link(new CspSegmentLink(axes, cfg));
  if (!link->configure(error)) return nullptr;
  return link;
}

CspSegmentLink::CspSegmentLink(AxisLink& axes, const CspConfig& cfg)
    : axes_(axes), cfg_(cfg), storage_(cfg.queue_slots), interp_({storage_.data(), storage_.size()}),
      torch_of_(256) {
  trace_.reserve(cfg.trace_reserve);
}

CspSegmentLink::~CspSegmentLink() { stop_clock(); }

bool CspSegmentLink::configure(std::string& error) {
  motion::MotionConfig<double> mc;
  mc.period = axes_.period_s();
  mc.accel = cfg_.accel_mm_s2;
  mc.corner_angle = cfg_.corner_angle_rad;
  mc.counts_per_mm = cfg_.counts_per_mm;
  if (interp_.configure(mc) != Status::ok) {
    error = "CSP link: the motion configuration is out of range";
    return false;
  }
  // The job starts where the drives stand.
  for (int a = 0; a < 2; ++a) target_[a] = axes_.axis(static_cast<std::size_t>(a)).actual;
  position_ = {static_cast<double>(target_[0]) / cfg_.counts_per_mm.x,
               static_cast<double>(target_[1]) / cfg_.counts_per_mm.y};
  tail_end_ = actual_ = position_;
  for (auto& s : sent_) s = {static_cast<std::int32_t>(target_[0]), static_cast<std::int32_t>(target_[1])};
  return true;
}

BoardStatus CspSegmentLink::status_locked() const {
  BoardStatus s;
  s.state = state_;
  s.credit = static_cast<std::uint16_t>(interp_.free_slots());
  s.faults = faults_;
  s.last_accepted = last_accepted_;
  s.executing = executing_;
  s.last_executed = last_executed_;
  s.position = position_;
  s.actual = actual_;
  s.torch = torch_;
  s.duplicates = duplicates_;
  return s;
}

LinkError CspSegmentLink::push(const SegmentCommand& seg, BoardStatus& status) {
  std::lock_guard<std::mutex> lock(mu_);
  if (seg.seq <= last_accepted_) {  // a resend of one already queued: drop it
    ++duplicates_;
    status = status_locked();
    return LinkError::none;
  }
  const char* why = nullptr;
  if (seg.seq != last_accepted_ + 1) why = "sequence gap";
  else if (state_ == BoardState::fault || state_ == BoardState::done || finish_) why = "not accepting segments now";
  else if (interp_.free_slots() == 0) why = "no credit";
  else if (std::fabs(seg.end.x * cfg_.counts_per_mm.x) >= kMaxCounts ||
           std::fabs(seg.end.y * cfg_.counts_per_mm.y) >= kMaxCounts)
    why = "end point beyond the drives' 32-bit position range";
  if (why == nullptr) {
    motion::PathSegment<double> p;
    p.geometry = seg.kind == SegmentKind::arc ? Segment<double>::arc(tail_end_, seg.end, seg.centre, seg.dir)
                                              : Segment<double>::line(tail_end_, seg.end);
    p.feed = seg.feed;
    p.sequence = seg.seq;
    if (interp_.push(p) != Status::ok) why = "the interpolator refused the segment (feed or geometry)";
  }
  if (why != nullptr) {
    std::snprintf(error_, sizeof error_, "segment %u refused: %s", static_cast<unsigned>(seg.seq), why);
    status = status_locked();
    return LinkError::rejected;
  }
  torch_of_[seg.seq % torch_of_.size()] = seg.torch ? 1 : 0;
  tail_end_ = seg.end;
  last_accepted_ = seg.seq;
  status = status_locked();
  changed_.notify_all();
  return LinkError::none;
}

LinkError CspSegmentLink::status(BoardStatus& status) {
  std::lock_guard<std::mutex> lock(mu_);
  status = status_locked();
  return LinkError::none;
}

void CspSegmentLink::fault_locked(std::uint16_t bit, const char* why) {
  // The safe state first: torch off, the queue dropped, the axes braking on
  // the path (setpoints keep going out every SYNC until they are at rest).
  torch_ = false;
  if (state_ != BoardState::fault)
    std::snprintf(error_, sizeof error_, "%s; last completed segment %u", why,
                  static_cast<unsigned>(last_executed_));
  state_ = BoardState::fault;
  faults_ |= bit;
  interp_.abort();
  changed_.notify_all();
}

LinkError CspSegmentLink::command(Command c) {
  std::lock_guard<std::mutex> lock(mu_);
  bool ok = true;
  switch (c) {
    case Command::start:  // from idle, or after a finished run: a new run (as the board)
      ok = state_ == BoardState::idle || state_ == BoardState::done;
      if (ok) {
        state_ = BoardState::running;
        finish_ = false;
      }
      break;
    case Command::hold:
      ok = state_ == BoardState::running;
      if (ok) {
        state_ = BoardState::hold;
        interp_.hold();
      }
      break;
    case Command::resume:
      ok = state_ == BoardState::hold;
      if (ok) {
        state_ = BoardState::running;
        interp_.resume();
        moving_ = true;
      }
      break;
    case Command::abort: fault_locked(kFaultAbort, "aborted by the host"); break;
    case Command::fault_reset:
      ok = state_ == BoardState::fault;
      if (ok) {
        // Drives that faulted are reset and enabled again by the next cycle.
        reset_axes_ = (faults_ & ~kFaultAbort) != 0;
        if (!reset_axes_) reset_locked();
      }
      break;
    case Command::finish: finish_ = true; break;
  }
  changed_.notify_all();
  if (!ok) {
    std::snprintf(error_, sizeof error_, "command %u not allowed in this state", static_cast<unsigned>(c));
    return LinkError::rejected;
  }
  return LinkError::none;
}

void CspSegmentLink::reset_locked() {
  state_ = BoardState::idle;
  faults_ = 0;
  finish_ = false;
  interp_.reset();
  // The next segment starts where the axes were last commanded to stop.
  tail_end_ = {static_cast<double>(target_[0]) / cfg_.counts_per_mm.x,
               static_cast<double>(target_[1]) / cfg_.counts_per_mm.y};
  dropped_through_ = last_accepted_;  // what the fault dropped never ran
}

bool CspSegmentLink::has_work_locked() const {
  if (reset_axes_) return true;
  if (state_ == BoardState::fault || state_ == BoardState::hold) return moving_ || !settled_;
  if (state_ != BoardState::running) return false;
  return interp_.free_slots() == 0 || finish_;
}

void CspSegmentLink::cycle() {
  std::unique_lock<std::mutex> lock(mu_);
  if (reset_axes_) {
    reset_axes_ = false;
    lock.unlock();
    const AxisError e = axes_.fault_reset();
    lock.lock();
    if (e != AxisError::none) {
      std::snprintf(error_, sizeof error_, "fault reset failed: %s", axes_.last_error());
      faults_ |= fault_bit(e);
    } else {
      // Enabling put the targets at the actual positions: start from there.
      target_[0] = axes_.axis(0).target;
      target_[1] = axes_.axis(1).target;
      reset_locked();
    }
    changed_.notify_all();
    return;
  }
  std::uint32_t running = 0;
  const bool stepping = state_ == BoardState::running || state_ == BoardState::hold || state_ == BoardState::fault;
  if (stepping) {
    const motion::Setpoint<double> sp = interp_.step();
    if (sp.state != motion::MotionState::idle) {
      target_[0] = sp.counts.x;
      target_[1] = sp.counts.y;
    }
    moving_ = sp.speed > 0.0;
    const bool active = sp.state == motion::MotionState::running || sp.state == motion::MotionState::stopping;
    running = active && interp_.queued() > 0 ? sp.sequence : 0;
    const std::uint32_t done = interp_.last_completed_sequence();
    const std::uint32_t from = last_executed_ > dropped_through_ ? last_executed_ : dropped_through_;
    for (std::uint32_t s = from + 1; s <= done && s > from; ++s) executed_.push_back(s);
    if (done > last_executed_) last_executed_ = done;
  } else {
    moving_ = false;
  }
  const std::int32_t tx = static_cast<std::int32_t>(target_[0]);
  const std::int32_t ty = static_cast<std::int32_t>(target_[1]);
  lock.unlock();
  axes_.set_target(0, tx);
  axes_.set_target(1, ty);
  const AxisError e = axes_.cycle();
  lock.lock();
  const AxisState& ax = axes_.axis(0);
  const AxisState& ay = axes_.axis(1);
  // 0x6064 from each TPDO, beside the setpoint of the SYNC it was sampled
  // at: the pair the following error compares, whatever the bus delay. A
  // drive silent for more than two SYNCs gives nothing to judge: its latest
  // setpoint stands in for both, and its heartbeat names it.
  const std::uint64_t c = axes_.counters().cycles;
  sent_[c % sent_.size()] = {tx, ty};
  std::int32_t cmd[2] = {tx, ty}, act[2] = {tx, ty};
  for (int a = 0; a < 2; ++a) {
    const AxisState& s = a == 0 ? ax : ay;
    if (s.feedback_cycle + 2 < c) continue;
    cmd[a] = sent_[s.feedback_cycle % sent_.size()][a];
    act[a] = s.actual;
  }
  position_ = {cmd[0] / cfg_.counts_per_mm.x, cmd[1] / cfg_.counts_per_mm.y};
  actual_ = {act[0] / cfg_.counts_per_mm.x, act[1] / cfg_.counts_per_mm.y};
  // At rest means the drives have caught up with the last setpoint.
  settled_ = ax.actual == tx && ay.actual == ty;
  if (e != AxisError::none) fault_locked(fault_bit(e), axes_.last_error());
  executing_ = state_ == BoardState::fault ? 0 : running;
  if (state_ != BoardState::fault) torch_ = running != 0 && torch_of_[running % torch_of_.size()] != 0;
  if (state_ == BoardState::running && finish_ && interp_.queued() == 0 && !moving_ && settled_) {
    state_ = BoardState::done;
    torch_ = false;
  }
  CspSample s;
  s.cycle = axes_.counters().cycles;
  s.seq = executing_;
  s.target[0] = tx;
  s.target[1] = ty;
  s.actual[0] = ax.actual;
  s.actual[1] = ay.actual;
  s.torch = torch_;
  trace_.push_back(s);
  changed_.notify_all();
}

void CspSegmentLink::clock_loop(bool paced) {
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mu_);
      if (!paced) changed_.wait(lock, [&] { return clock_stop_ || has_work_locked(); });
      if (clock_stop_) return;
    }
    cycle();  // paced: blocks until the SYNC is due
  }
}

void CspSegmentLink::run_clock(bool paced) {
  clock_stop_ = false;
  clock_ = std::thread([this, paced] { clock_loop(paced); });
}

void CspSegmentLink::stop_clock() {
  if (!clock_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mu_);
    clock_stop_ = true;
    changed_.notify_all();
  }
  clock_.join();
}

bool CspSegmentLink::wait_until(const std::function<bool(const BoardStatus&)>& pred, double timeout_s) {
  std::unique_lock<std::mutex> lock(mu_);
  return changed_.wait_for(lock, std::chrono::duration<double>(timeout_s), [&] { return pred(status_locked()); });
}

const char* CspSegmentLink::last_error() const { return error_; }

std::vector<CspSample> CspSegmentLink::trace() const {
  std::lock_guard<std::mutex> lock(mu_);
  return trace_;
}

std::vector<std::uint32_t> CspSegmentLink::executed() const {
  std::lock_guard<std::mutex> lock(mu_);
  return executed_;
}

}  // namespace kerf::hal
