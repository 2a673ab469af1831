#include "kerf/hal/can/csp_segment_link.hpp"

#include "kerf/hal/canopen.hpp"

#include <pthread.h>
#include <sched.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

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
  if (cfg.z.configured() && (axes.axis_count() < 3 || !(cfg.z_counts_per_mm > 0))) {
    error = "CSP link: a z axis needs a third drive and counts per mm > 0";
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
    : axes_(axes), cfg_(cfg), storage_(cfg.queue_slots), motion_({storage_.data(), storage_.size()}),
      ring_(cfg.queue_slots), trace_(cfg.trace_capacity), executed_(cfg.executed_capacity) {
  if (cfg.sink_capacity > 0) sink_ = std::make_unique<SpscQueue<CspRecord>>(cfg.sink_capacity);
}

CspSegmentLink::~CspSegmentLink() {
  stop_clock();
  stop_sink();
}

bool CspSegmentLink::configure(std::string& error) {
  motion::MotionConfig<double> mc;
  mc.period = axes_.period_s();
  mc.accel = cfg_.accel_mm_s2;
  mc.corner_angle = cfg_.corner_angle_rad;
  mc.vad = cfg_.vad;
  mc.counts_per_mm = cfg_.counts_per_mm;
  if (motion_.configure(mc) != Status::ok) {
    error = "CSP link: the motion configuration is out of range";
    return false;
  }
  // The job starts where the drives stand.
  for (int a = 0; a < 2; ++a) target_[a] = axes_.axis(static_cast<std::size_t>(a)).actual;
  position_ = {static_cast<double>(target_[0]) / cfg_.counts_per_mm.x,
               static_cast<double>(target_[1]) / cfg_.counts_per_mm.y};
  actual_ = position_;
  for (auto& s : sent_) s = {static_cast<std::int32_t>(target_[0]), static_cast<std::int32_t>(target_[1])};
  exec_.emplace(motion_, Span<SegmentCommand>{ring_.data(), ring_.size()}, position_);
  exec_->set_soft_limits(cfg_.soft_limits);
  if (has_z()) {
    cfg_.z.period = axes_.period_s();  // z steps with the SYNC
    exec_->configure_z(cfg_.z, static_cast<double>(axes_.axis(2).actual) / cfg_.z_counts_per_mm);
  }
  return true;
}

std::int32_t CspSegmentLink::z_counts() const {
  return static_cast<std::int32_t>(std::llround(exec_->z() * cfg_.z_counts_per_mm));
}

BoardStatus CspSegmentLink::status_locked() const {
  BoardStatus s = status_of(*exec_);
  s.position = position_;  // the setpoint the drives' feedback answers
  s.actual = actual_;      // the drives' 0x6064
  s.homed = homed_;
  s.homing = homing_;
  return s;
}

LinkError CspSegmentLink::push(const SegmentCommand& seg, BoardStatus& status) {
  std::lock_guard<std::mutex> lock(mu_);
  const char* why = nullptr;
  if (seg.seq > exec_->last_accepted() && (std::fabs(seg.end.x * cfg_.counts_per_mm.x) >= kMaxCounts ||
                                           std::fabs(seg.end.y * cfg_.counts_per_mm.y) >= kMaxCounts ||
                                           (seg.z_move && std::fabs(seg.z * cfg_.z_counts_per_mm) >= kMaxCounts)))
    why = "end point beyond the drives' 32-bit position range";
  switch (why != nullptr ? motion::BoardAccept::invalid : exec_->accept(seg)) {
    case motion::BoardAccept::queued:
    case motion::BoardAccept::duplicate: break;  // a resend of one already queued: dropped, counted
    case motion::BoardAccept::gap: why = "sequence gap"; break;
    case motion::BoardAccept::full: why = "no credit"; break;
    case motion::BoardAccept::invalid:
      if (why == nullptr) why = "not accepting segments now";
      break;
  }
  status = status_locked();
  if (why != nullptr) {
    std::snprintf(error_, sizeof error_, "segment %u refused: %s", static_cast<unsigned>(seg.seq), why);
    return LinkError::rejected;
  }
  changed_.notify_all();
  return LinkError::none;
}

LinkError CspSegmentLink::status(BoardStatus& status) {
  std::lock_guard<std::mutex> lock(mu_);
  status = status_locked();
  return LinkError::none;
}

void CspSegmentLink::set_homed(std::uint8_t bits) {
  std::lock_guard<std::mutex> lock(mu_);
  homed_ = bits;
}

LinkError CspSegmentLink::home(const HomeCommand& h, const std::function<bool()>& stop) {
  std::lock_guard<std::mutex> lock(mu_);  // the clock waits: the homing runs the SYNC itself
  const BoardState st = exec_->state();
  if (h.dir == 0) {  // "here" (kerf's own GPIO search): not offered over CAN
    std::snprintf(error_, sizeof error_, "home: dir 0 (here) is for the Modbus board; a drive homes on its own input");
    return LinkError::rejected;
  }
  if (h.axis < 0 || h.axis > 2 || (h.axis == 2 && !has_z()) || (st != BoardState::idle && st != BoardState::done) ||
      !exec_->at_rest()) {
    std::snprintf(error_, sizeof error_, "home: not allowed now (axis %d)", h.axis);
    return LinkError::rejected;
  }
  const double cpm = h.axis == 0 ? cfg_.counts_per_mm.x : h.axis == 1 ? cfg_.counts_per_mm.y : cfg_.z_counts_per_mm;
  DriveHoming d;
  d.method = h.dir < 0 ? canopen::kHomeNegativeSwitch : canopen::kHomePositiveSwitch;
  d.search_speed = static_cast<std::uint32_t>(std::lround(h.search_speed * cpm));
  d.latch_speed = static_cast<std::uint32_t>(std::lround(h.latch_speed * cpm));
  d.home_offset = static_cast<std::int32_t>(std::lround(h.home_position * cpm));
  d.max_travel = static_cast<std::uint32_t>(std::lround(h.search_distance * cpm));
  homed_ = static_cast<std::uint8_t>(homed_ & ~(1u << h.axis));
  DriveHomingResult r = DriveHomingResult::drive_error;
  const AxisError e = axes_.home(static_cast<std::size_t>(h.axis), d, r, stop);
  homing_ = r == DriveHomingResult::attained ? HomingState::done
            : r == DriveHomingResult::no_switch ? HomingState::no_switch
                                                : HomingState::aborted;
  if (homing_ == HomingState::done) homed_ = static_cast<std::uint8_t>(homed_ | (1u << h.axis));
  // The job starts where the drives now stand (the executor takes a new
  // position only out of fault: an empty fault, then a reset there).
  for (int a = 0; a < 2; ++a) target_[a] = axes_.axis(static_cast<std::size_t>(a)).actual;
  position_ = {static_cast<double>(target_[0]) / cfg_.counts_per_mm.x, static_cast<double>(target_[1]) / cfg_.counts_per_mm.y};
  actual_ = position_;
  for (auto& s : sent_) s = {static_cast<std::int32_t>(target_[0]), static_cast<std::int32_t>(target_[1])};
  exec_->fault(0);
  exec_->reset(position_);
  if (has_z()) exec_->configure_z(cfg_.z, static_cast<double>(axes_.axis(2).actual) / cfg_.z_counts_per_mm);
  if (homing_ != HomingState::done) exec_->fault(e != AxisError::none ? kFaultDrive : r == DriveHomingResult::aborted ? kFaultAbort : kFaultHoming);
  changed_.notify_all();
  if (e != AxisError::none) {
    std::snprintf(error_, sizeof error_, "home: %s", axes_.last_error());
    return LinkError::rejected;
  }
  return LinkError::none;
}

void CspSegmentLink::fault_locked(std::uint16_t bit, const char* why) {
  // The safe state first: torch off, the queue dropped, the axes braking on
  // the path (setpoints keep going out every SYNC until they are at rest).
  if (exec_->state() != BoardState::fault)
    std::snprintf(error_, sizeof error_, "%s; last completed segment %u", why,
                  static_cast<unsigned>(exec_->last_executed()));
  exec_->fault(bit);
  changed_.notify_all();
}

LinkError CspSegmentLink::command(Command c) {
  std::lock_guard<std::mutex> lock(mu_);
  bool ok = true;
  if (c == Command::abort) {
    fault_locked(kFaultAbort, "aborted by the host");
  } else if (c == Command::fault_reset && exec_->state() == BoardState::fault &&
             (exec_->faults() & ~kFaultAbort) != 0) {
    reset_axes_ = true;  // drives that faulted are reset and enabled again by the next cycle
  } else {
    ok = exec_->command(c);
  }
  changed_.notify_all();
  if (!ok) {
    std::snprintf(error_, sizeof error_, "command %u not allowed in this state", static_cast<unsigned>(c));
    return LinkError::rejected;
  }
  return LinkError::none;
}

bool CspSegmentLink::has_work_locked() const {
  if (reset_axes_ || exec_->needs_step(false)) return true;
  const BoardState st = exec_->state();
  return (st == BoardState::fault || st == BoardState::hold) && (moving_ || !settled_);
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
      exec_->fault(fault_bit(e));
    } else {
      // Enabling put the targets at the actual positions: start from there.
      target_[0] = axes_.axis(0).target;
      target_[1] = axes_.axis(1).target;
      exec_->reset({static_cast<double>(target_[0]) / cfg_.counts_per_mm.x,
                    static_cast<double>(target_[1]) / cfg_.counts_per_mm.y});
      if (has_z()) exec_->configure_z(cfg_.z, static_cast<double>(axes_.axis(2).target) / cfg_.z_counts_per_mm);
    }
    changed_.notify_all();
    return;
  }
  const motion::BoardStep<double> e = exec_->step(true);
  moving_ = e.stepped && exec_->moving();
  if (e.stepped) {
    const motion::Counts c = motion_.counts();
    target_[0] = c.x;
    target_[1] = c.y;
  }
  for (std::uint32_t s = e.completed_from + 1; s <= e.completed_to; ++s) {
    executed_.push(s);
    CspRecord r;
    r.executed = true;
    r.seq = s;
    record(r);
  }
  const std::int32_t tx = static_cast<std::int32_t>(target_[0]);
  const std::int32_t ty = static_cast<std::int32_t>(target_[1]);
  const std::int32_t tz = has_z() ? z_counts() : 0;
  lock.unlock();
  axes_.set_target(0, tx);
  axes_.set_target(1, ty);
  if (has_z()) axes_.set_target(2, tz);
  const AxisError err = axes_.cycle();
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
  settled_ = ax.actual == tx && ay.actual == ty && (!has_z() || axes_.axis(2).actual == tz);
  if (err != AxisError::none) fault_locked(fault_bit(err), axes_.last_error());
  if (settled_) exec_->drives_settled();
  CspSample s;
  s.cycle = axes_.counters().cycles;
  s.seq = exec_->executing();
  s.target[0] = tx;
  s.target[1] = ty;
  s.actual[0] = ax.actual;
  s.actual[1] = ay.actual;
  s.target_z = tz;
  s.torch = exec_->torch();
  trace_.push(s);
  CspRecord r;
  r.sample = s;
  record(r);
  changed_.notify_all();
}

void CspSegmentLink::record(const CspRecord& r) {
  if (sink_ && !sink_->try_push(r)) sink_dropped_.fetch_add(1, std::memory_order_relaxed);
}

std::size_t CspSegmentLink::drain(const SinkFn& fn) {
  if (!sink_) return 0;
  std::lock_guard<std::mutex> lock(drain_mu_);
  std::size_t n = 0;
  CspRecord r;
  while (sink_->try_pop(r)) {
    fn(r);
    ++n;
  }
  return n;
}

void CspSegmentLink::run_sink(SinkFn fn, double period_s) {
  if (!sink_ || sink_thread_.joinable()) return;
  sink_stop_.store(false);
  sink_thread_ = std::thread([this, fn = std::move(fn), period_s] {
    sched_param sp{};  // not real-time: a thread started from a SCHED_FIFO one inherits its policy
    pthread_setschedparam(pthread_self(), SCHED_OTHER, &sp);
    while (!sink_stop_.load(std::memory_order_acquire)) {
      drain(fn);
      std::this_thread::sleep_for(std::chrono::duration<double>(period_s));
    }
    drain(fn);  // what the cycle pushed before the stop
  });
}

void CspSegmentLink::stop_sink() {
  if (!sink_thread_.joinable()) return;
  sink_stop_.store(true, std::memory_order_release);
  sink_thread_.join();
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
  return trace_.copy();
}

std::vector<std::uint32_t> CspSegmentLink::executed() const {
  std::lock_guard<std::mutex> lock(mu_);
  return executed_.copy();
}

std::uint64_t CspSegmentLink::trace_total() const {
  std::lock_guard<std::mutex> lock(mu_);
  return trace_.total();
}

}  // namespace kerf::hal
