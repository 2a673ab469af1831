// What a motion board speaks, whatever carries it (Modbus registers, a
// host-side CANopen link, a board's own firmware): the segment as the board
// receives it, the board's states and commands, and what one period of its
// motion stage reports. hal/segment_link.hpp names these for the links.
#pragma once

#include <cstdint>

#include "kerf/geom/segment.hpp"

namespace kerf::motion {

// One segment as the board receives it: the start is where the previous one
// ended (or the board's position for the first). A z move (z_move) is an
// item of its own: Z alone to `z` at rest in XY, run once every segment
// before it has finished; its `end` is the XY end of the item before (the
// board checks it), kind line, dir 0, centre unused, feed the Z feed.
template <class S>
struct BoardSegment {
  std::uint32_t seq = 0;  // 1, 2, 3 ... in streaming order; 0 is "none"
  SegmentKind kind = SegmentKind::line;
  Vec2<S> end{};     // mm
  Vec2<S> centre{};  // mm, arcs only
  std::int8_t dir = 0;  // +1 CCW, -1 CW, 0 line
  S feed{};             // mm/s
  bool torch = true;    // cut (torch on) or travel
  bool z_move = false;  // Z alone (above)
  S z{};                // mm, the z move's end
};

enum class BoardState : std::uint8_t { idle = 0, running = 1, hold = 2, done = 3, fault = 4 };

enum class BoardCommand : std::uint16_t {
  start = 1,        // begin executing the queue
  hold = 2,         // feed hold: ramp to a stop, keep the queue
  resume = 3,
  abort = 4,        // stop now, torch off, clear the queue, state fault
  fault_reset = 5,  // from fault back to idle, once the axes are at rest (latched while braking)
  finish = 6,       // no more segments: an empty queue then means done
};

// How the board took a segment.
enum class BoardAccept : std::uint8_t {
  queued,
  duplicate,  // a resend of one it already has: dropped and counted
  gap,        // not the next sequence number
  full,       // no credit
  invalid,    // not taking segments now (fault, done, or finished)
};

// The fault bits the executor itself raises (hal::FaultBit lists them all).
inline constexpr std::uint16_t kBoardFaultAbort = 1u << 0;       // abort command
inline constexpr std::uint16_t kBoardFaultBadSegment = 1u << 2;  // the motion refused a segment
                                                                  // (or a z move: no z axis, XY off)

// One period of the motion stage (the interpolator, or a stand-in).
template <class S>
struct MotionStep {
  Vec2<S> position{};                // what the drives hold after this period, mm
  std::uint32_t running = 0;         // sequence number being run, 0 when none
  std::uint32_t last_completed = 0;  // highest sequence number finished
  bool moving = false;               // travelled this period
  bool at_rest = true;               // not moving and nothing left to run
  bool thc_lock = true;              // below vad of the cut feed: hold the torch height
};

// One period of the board.
template <class S>
struct BoardStep {
  Vec2<S> position{};
  std::uint32_t executing = 0;  // 0 when idle or in fault
  bool torch = false;
  bool thc_lock = true;  // the stage's MotionStep::thc_lock (raw: not masked by the torch)
  bool stepped = false;  // the motion stage ran this period
  S z{};                 // mm, the z axis (0 on a board without one)
  // The segments completed_from + 1 .. completed_to finished this period.
  std::uint32_t completed_from = 0;
  std::uint32_t completed_to = 0;
};

}  // namespace kerf::motion
