// hal::SegmentLink: streams whole segments (line or arc, end, centre,
// direction, feed, sequence number) into a motion board's queue, with
// credit-based flow control. Sequence numbers make a resend idempotent: the
// board drops a number it has already accepted, so after any link fault no
// segment is lost or run twice. Implementations allocate only when they are
// created or (re)connect, never in push/status/command.
#pragma once

#include <cstdint>

#include "kerf/geom/segment.hpp"

namespace kerf::hal {

// One segment as the board receives it: the start is where the previous one
// ended (or the board's position for the first).
struct SegmentCommand {
  std::uint32_t seq = 0;  // 1, 2, 3 ... in streaming order; 0 is "none"
  SegmentKind kind = SegmentKind::line;
  Vec2<double> end{};     // mm
  Vec2<double> centre{};  // mm, arcs only
  std::int8_t dir = 0;    // +1 CCW, -1 CW, 0 line
  double feed = 0.0;      // mm/s
  bool torch = true;      // cut (torch on) or travel
};

enum class BoardState : std::uint8_t { idle = 0, running = 1, hold = 2, done = 3, fault = 4 };

// Fault bits the board reports.
enum FaultBit : std::uint16_t {
  kFaultNone = 0,
  kFaultAbort = 1u << 0,         // abort command
  kFaultLinkWatchdog = 1u << 1,  // no request from the host for too long while running
  kFaultBadSegment = 1u << 2,    // a segment the executor refused (zero length, bad arc)
  kFaultStarved = 1u << 3,       // queue ran empty while running, before "finish"
  kFaultDrive = 1u << 4,         // a drive reported a fault (following error, overcurrent ...)
  // Cyclic drives (CspSegmentLink over CANopen CiA 402; kFaultDrive above also
  // covers a drive that left "operation enabled", refused enable or did not answer):
  kFaultHeartbeat = 1u << 5,  // a drive's heartbeat stopped
  kFaultEmcy = 1u << 6,       // a drive sent an emergency message
  kFaultBusOff = 1u << 7,     // the CAN controller went bus-off
  kFaultSend = 1u << 8,       // a cyclic frame could not be queued
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
  bool torch = false;
  std::uint16_t duplicates = 0;    // resends the board dropped (wraps)
};

enum class Command : std::uint16_t {
  start = 1,        // begin executing the queue
  hold = 2,         // feed hold: ramp to a stop, keep the queue
  resume = 3,
  abort = 4,        // stop now, torch off, clear the queue, state fault
  fault_reset = 5,  // from fault back to idle, once the axes are at rest (latched while braking)
  finish = 6,       // no more segments: an empty queue then means done
};

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
