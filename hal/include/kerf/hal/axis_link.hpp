// hal::AxisLink: cyclic per-axis position setpoints, as CANopen CiA 402
// Cyclic Synchronous Position does it. The host interpolates; each cycle()
// is one SYNC period: the targets set since the last cycle go out, then the
// SYNC, and the drives' feedback of the previous period comes in. Bring-up
// (NMT, SDO setup) and the 402 enable sequence are separate calls that run
// cycles themselves. Implementations allocate only when they are created.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

namespace kerf::hal {

enum class AxisError : std::uint8_t {
  none = 0,
  timeout,         // a drive did not answer (SDO, state change) in time
  sdo_abort,       // a drive aborted an SDO transfer
  enable_refused,  // a drive did not reach "operation enabled"
  drive_fault,     // a drive's statusword shows fault
  heartbeat_lost,  // no heartbeat within the consumer time
  emcy,            // a drive sent an emergency message
  bus_off,         // the CAN controller is bus-off
  send_failed,     // a frame could not be queued (full send queue, OS error)
  not_enabled,     // cycle() before enable()
};

const char* to_string(AxisError e);

struct AxisState {
  std::uint8_t node = 0;            // CANopen node id
  std::uint16_t statusword = 0;     // 0x6041, from the last TPDO
  std::int32_t actual = 0;          // 0x6064, counts
  std::int32_t target = 0;          // 0x607A, counts, last sent
  std::uint16_t controlword = 0;    // 0x6040, last sent
  std::uint16_t emcy_code = 0;      // last EMCY error code, 0 when none
  std::uint64_t feedback_cycle = 0; // cycle whose TPDO was last seen
};

// Frames refused as untrustworthy, by kind.
struct AxisCounters {
  std::uint64_t cycles = 0;
  std::uint64_t late_syncs = 0;   // SYNC deadlines missed by more than a period (wall clock only)
  std::uint64_t bad_dlc = 0;      // a known COB-ID with the wrong length
  std::uint64_t unknown_cob = 0;  // a COB-ID no configured node uses
  std::uint64_t sdo_aborts = 0;
  std::uint64_t stray_sdo = 0;    // an SDO reply nobody asked for, or for another object
  std::uint64_t emcy = 0;
  std::uint64_t error_passive = 0;  // times the bus went error-passive
};

// One drive's homing (CiA 402 mode 6), in the drive's units.
struct DriveHoming {
  std::int8_t method = 17;          // 17: negative switch, 18: positive (0x6098)
  std::uint32_t search_speed = 0;   // counts/s (0x6099 sub 1)
  std::uint32_t latch_speed = 0;    // counts/s (0x6099 sub 2)
  std::int32_t home_offset = 0;     // counts: the position the home point becomes (0x607C)
  std::uint32_t max_travel = 0;     // counts: the master halts the drive past this (the search distance)
};

enum class DriveHomingResult : std::uint8_t { attained, no_switch, aborted, drive_error };

class AxisLink {
 public:
  virtual ~AxisLink() = default;
  virtual std::size_t axis_count() const = 0;
  virtual double period_s() const = 0;
  // NMT reset, SDO setup (CSP mode, interpolation period, PDO mapping,
  // heartbeat), NMT start.
  virtual AxisError bring_up() = 0;
  // shutdown -> switch on -> enable operation on every axis; the targets
  // start at the actual positions.
  virtual AxisError enable() = 0;
  virtual AxisError disable() = 0;
  // Fault reset (rising edge of controlword bit 7) and enable again.
  virtual AxisError fault_reset() = 0;
  virtual void set_target(std::size_t axis, std::int32_t counts) = 0;
  virtual AxisError cycle() = 0;
  virtual const AxisState& axis(std::size_t i) const = 0;
  virtual const AxisCounters& counters() const = 0;
  // Homes one axis in the drive's homing mode (blocking: it runs the SYNC
  // cycles itself); `stop` halts it. A link that cannot home answers not_enabled.
  virtual AxisError home(std::size_t, const DriveHoming&, DriveHomingResult& result, const std::function<bool()>&) {
    result = DriveHomingResult::drive_error;
    return AxisError::not_enabled;
  }
  // Text of the last error, naming the axis (static storage, no allocation).
  virtual const char* last_error() const = 0;
};

}  // namespace kerf::hal
