// The motion board's executor: the segment queue the host fills by sequence
// number, the credit it reports, the command state machine, and the hand-over
// of queued segments to a motion stage that turns them into setpoints. One
// implementation for every board: the simulated Modbus board (sim/), the
// host-side CiA 402 link (hal/can/) and a board's own firmware (Cortex-M).
// Locking, time, tracing and I/O stay with the caller; this is plain state.
//
// Rules:
// - accept(): a number at or below the last accepted is a resend, dropped and
//   counted; only last + 1 is queued; nothing is queued in fault, when done
//   or after finish; credit is the queue's free slots.
// - Queued segments go to the motion stage while running, as soon as it has
//   room, so a stage with look-ahead sees what comes next. A segment the
//   stage refuses (bad geometry or feed) is a fault (kBoardFaultBadSegment).
// - start: idle or done -> running. hold: running -> hold (the stage brakes
//   on the path). resume: hold -> running. abort, or fault(): the safe state
//   at once (torch off, the queue dropped, the stage braking on the path).
//   fault_reset is latched while the stage still brakes and takes effect at
//   rest (the next segment then starts where the axes stopped).
// - finish: no more segments; running with an empty queue and the stage at
//   rest (and the drives settled, when the caller says so) is done.
// - The torch follows the sequence number the stage is running.
// - A z move (BoardSegment::z_move) waits until every segment before it has
//   finished and the stage is at rest, then runs alone on the z axis
//   (AxisMove, within configure_z's limits); the segments after it wait for
//   it. Its XY end must be the previous end (within kZXyTolerance), and a
//   board with no z axis refuses it: both are kBoardFaultBadSegment.
//
// Motion (the stage) provides: free_slots(), push(from, segment) -> bool,
// step() -> MotionStep<S>, hold(), resume(), abort(), reset(at). It is a
// template parameter: a board's firmware binds the interpolator with no
// virtual call; the simulator binds an interface (sim::SegmentExecutor).
#pragma once

#include <cstddef>
#include <cstdint>

#include "kerf/core/span.hpp"
#include "kerf/motion/axis_move.hpp"
#include "kerf/motion/board_protocol.hpp"
#include "kerf/motion/soft_limits.hpp"

namespace kerf::motion {

template <class S, class Motion>
class BoardExecutor {
 public:
  // Sequence numbers of segments in the queue and in the stage together
  // must fit this window (the torch flag is kept by number, modulo it).
  static constexpr std::size_t kTorchWindow = 512;
  // How far a z move's XY end may be from the previous end, mm (the links
  // carry whole micrometres; a fault leaves the axes between counts).
  static constexpr double kZXyTolerance = 0.002;

  // queue: the board's slots (its size is the credit); motion: configured,
  // empty, and outliving the executor; start: where the axes stand.
  BoardExecutor(Motion& motion, Span<BoardSegment<S>> queue, Vec2<S> start);

  BoardAccept accept(const BoardSegment<S>& seg);
  bool command(BoardCommand c);  // false: not allowed in this state
  // A fault (bits are the caller's FaultBit set): torch off, the queue
  // dropped, the stage braking on the path. From any state.
  void fault(std::uint16_t bits);
  // Fault -> idle now, the axes at `at` (the caller has reset the drives,
  // which took their own positions as the setpoint).
  void reset(Vec2<S> at);
  // The z axis's limits (none by default: z moves are refused), and where it stands.
  void configure_z(const AxisLimits<S>& limits, S at) {
    z_.configure(limits);
    z_.reset(at);
  }
  // A segment that leaves these is refused before it moves: a fault
  // (kBoardFaultSoftLimit), as any refused segment (soft_limits.hpp).
  void set_soft_limits(const SoftLimits<S>& limits) { limits_ = limits; }

  // One servo period. A caller whose drives follow the setpoint with a lag
  // passes wait_for_drives and calls drives_settled() once they hold it:
  // only then can the job be done.
  BoardStep<S> step(bool wait_for_drives = false);
  void drives_settled() { finish_if_done(); }
  // Whether step() has anything to do. paced: wall-clock periods; otherwise
  // (as fast as possible) a running board steps only while segments wait in
  // its queue or the job is finished, so a slow host cannot starve it.
  bool needs_step(bool paced) const;

  BoardState state() const { return state_; }
  bool active() const { return state_ == BoardState::running || state_ == BoardState::hold; }
  std::uint16_t faults() const { return faults_; }
  std::uint16_t credit() const { return static_cast<std::uint16_t>(queue_.size() - count_); }
  std::size_t queued() const { return count_; }
  std::uint32_t last_accepted() const { return last_accepted_; }
  std::uint32_t executing() const { return executing_; }
  std::uint32_t last_executed() const { return last_executed_; }
  std::uint16_t duplicates() const { return duplicates_; }
  Vec2<S> position() const { return position_; }
  S z() const { return z_.position(); }
  bool torch() const { return torch_; }
  bool thc_lock() const { return thc_lock_; }  // the last step's: below vad of the cut feed
  bool moving() const { return moving_; }
  bool at_rest() const { return !busy_; }
  bool finishing() const { return finish_; }

 private:
  void hand_over();  // queued segments into the stage while it has room
  bool start_z(const BoardSegment<S>& seg);
  void reset_now(Vec2<S> at);
  void finish_if_done();
  bool torch_of(std::uint32_t seq) const;
  void set_torch_of(std::uint32_t seq, bool on);

  Motion& motion_;
  AxisMove<S> z_;
  Span<BoardSegment<S>> queue_;
  std::size_t head_ = 0, count_ = 0;
  BoardState state_ = BoardState::idle;
  std::uint16_t faults_ = 0;
  std::uint16_t duplicates_ = 0;
  std::uint32_t last_accepted_ = 0, executing_ = 0, last_executed_ = 0;
  std::uint32_t dropped_through_ = 0;  // numbers up to here were dropped by a fault
  bool finish_ = false;
  bool torch_ = false;
  bool thc_lock_ = true;
  bool busy_ = false;           // the stage is moving or has segments
  bool moving_ = false;         // it travelled in the last period
  bool reset_pending_ = false;  // fault_reset taken while braking: reset at rest
  Vec2<S> position_{};
  Vec2<S> tail_end_{};  // where the last segment given to the stage ends
  SoftLimits<S> limits_{};  // default: unlimited
  std::uint32_t torch_bits_[kTorchWindow / 32] = {};
};

}  // namespace kerf::motion

#include "kerf/motion/board_executor_impl.hpp"
