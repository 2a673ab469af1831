// hal::SegmentLink: streams whole segments (line or arc, end, centre,
// direction, feed, sequence number) into a motion board's queue, with
// credit-based flow control. Sequence numbers make a resend idempotent: the
// board drops a number it has already accepted, so after any link fault no
// segment is lost or run twice. Implementations allocate only when they are
// created or (re)connect, never in push/status/command.
#pragma once

#include <cstdint>
#include <functional>

#include "kerf/motion/board_protocol.hpp"
#include "kerf/motion/soft_limits.hpp"

namespace kerf::hal {

// One segment as the board receives it (the start is where the previous one
// ended), its states and commands: core/motion's board protocol, which the
// boards' shared executor (motion/board_executor.hpp) runs.
using SegmentCommand = motion::BoardSegment<double>;
using BoardState = motion::BoardState;
using Command = motion::BoardCommand;

// Fault bits the board reports.
enum FaultBit : std::uint16_t {
  kFaultNone = 0,
  kFaultAbort = motion::kBoardFaultAbort,  // abort command
  kFaultLinkWatchdog = 1u << 1,  // no request from the host for too long while running
  kFaultBadSegment = motion::kBoardFaultBadSegment,  // a segment the executor refused (zero length, bad arc)
  kFaultStarved = 1u << 3,       // queue ran empty while running, before "finish"
  kFaultDrive = 1u << 4,         // a drive reported a fault (following error, overcurrent ...)
  // Cyclic drives (CspSegmentLink over CANopen CiA 402; kFaultDrive above also
  // covers a drive that left "operation enabled", refused enable or did not answer):
  kFaultHeartbeat = 1u << 5,  // a drive's heartbeat stopped
  kFaultEmcy = 1u << 6,       // a drive sent an emergency message
  kFaultBusOff = 1u << 7,     // the CAN controller went bus-off
  kFaultSend = 1u << 8,       // a cyclic frame could not be queued
  kFaultSoftLimit = motion::kBoardFaultSoftLimit,  // a segment outside the soft limits (motion/soft_limits.hpp)
  kFaultHoming = 1u << 10,    // homing failed: the switch never tripped within the search distance
};

// Homing of one axis, run by the board (Modbus) or the drive (CiA 402 mode 6):
// search towards the switch at search_speed for at most search_distance,
// back off by backoff, latch at latch_speed; the latch point becomes
// home_position. Speeds in mm/s, lengths in mm.
struct HomeCommand {
  int axis = 0;          // 0 x, 1 y, 2 z
  int dir = -1;          // -1: the switch is towards negative, +1 towards positive;
                         // 0: no search, where the axis stands becomes home_position
                         // (after kerf's own search on a GPIO switch; CiA 402 method 37)
  double search_speed = 20;
  double latch_speed = 1;
  double search_distance = 1000;
  double backoff = 2;
  double home_position = 0;
};

// Where a homing cycle is (status register 23, hal/modbus/REGISTERS.md).
enum class HomingState : std::uint8_t {
  none = 0, search = 1, backoff = 2, latch = 3, done = 4, no_switch = 5, aborted = 6,
};
inline const char* to_string(HomingState s) {
  switch (s) {
    case HomingState::none: return "not homing";
    case HomingState::search: return "searching for the switch";
    case HomingState::backoff: return "backing off the switch";
    case HomingState::latch: return "latching";
    case HomingState::done: return "homed";
    case HomingState::no_switch: return "the switch never tripped within the search distance";
    case HomingState::aborted: return "homing aborted";
  }
  return "?";
}

struct BoardStatus {
  BoardState state = BoardState::idle;
  std::uint16_t credit = 0;        // free queue slots
  std::uint16_t faults = 0;        // FaultBit set
  std::uint32_t last_accepted = 0; // highest sequence number queued
  std::uint32_t executing = 0;     // sequence number now running, 0 when none
  std::uint32_t last_executed = 0; // highest sequence number completed
  Vec2<double> position{};         // mm, commanded: where the interpolator has put the axes
  // mm, measured (encoder, CiA 402 0x6064). A board without feedback reports
  // its commanded position here; the controller checks the gap (following error).
  Vec2<double> actual{};
  double z = 0;  // mm, commanded z (0 on a machine without a z axis)
  bool torch = false;
  bool thc_lock = true;  // speed below vad of the cut feed: torch-height control holds
  std::uint16_t duplicates = 0;    // resends the board dropped (wraps)
  std::uint8_t homed = 0;          // bit 0 x, bit 1 y, bit 2 z: homed since power-up
  HomingState homing = HomingState::none;
};

// The status of a board run by motion::BoardExecutor.
template <class Executor>
BoardStatus status_of(const Executor& e) {
  BoardStatus s;
  s.state = e.state();
  s.credit = e.credit();
  s.faults = e.faults();
  s.last_accepted = e.last_accepted();
  s.executing = e.executing();
  s.last_executed = e.last_executed();
  s.position = e.position();
  s.z = static_cast<double>(e.z());
  s.torch = e.torch();
  s.thc_lock = e.thc_lock();
  s.duplicates = e.duplicates();
  return s;
}

enum class LinkError : std::uint8_t {
  none = 0,
  timeout,      // no valid reply within the response timeout, after every retry
  exception,    // the board answered with a Modbus exception
  malformed,    // a reply that failed validation (unit id, length, CRC, content)
  disconnected, // could not (re)connect
  rejected,     // the board refused the segment (sequence gap, no credit, bad values)
  busy,         // the board answered "busy" (or "acknowledge") to every retry
};

const char* to_string(LinkError e);

class SegmentLink {
 public:
  virtual ~SegmentLink() = default;
  // Queues one segment. On success `status` is the board's state right after
  // the write, so credit is known without another request.
  virtual LinkError push(const SegmentCommand& seg, BoardStatus& status) = 0;
  virtual LinkError status(BoardStatus& status) = 0;
  virtual LinkError command(Command c) = 0;
  // Homes one axis: the board runs it (Modbus: this starts it, status()
  // follows it, `stop` is not called) or the drive does (CAN: this returns
  // when it has ended, halting it when `stop` returns true). A link that
  // cannot home answers rejected.
  virtual LinkError home(const HomeCommand&, const std::function<bool()>& /*stop*/) { return LinkError::rejected; }
  // Transactions sent again after a failed attempt, since creation.
  virtual std::uint64_t resends() const = 0;
  // Text of the last error, for the operator (static storage, no allocation).
  virtual const char* last_error() const = 0;
};

}  // namespace kerf::hal
