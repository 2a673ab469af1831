// hal::SegmentLink: streams whole segments (line or arc, end, centre,
// direction, feed, sequence number) into a motion board's queue, with
// credit-based flow control. Sequence numbers make a resend idempotent: the
// board drops a number it has already accepted, so after any link fault no
// segment is lost or run twice. Implementations allocate only when they are
// created or (re)connect, never in push/status/command.
#pragma once

#include <cstdint>

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
};

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
  // Transactions sent again after a failed attempt, since creation.
  virtual std::uint64_t resends() const = 0;
  // Text of the last error, for the operator (static storage, no allocation).
  virtual const char* last_error() const = 0;
};

}  // namespace kerf::hal
