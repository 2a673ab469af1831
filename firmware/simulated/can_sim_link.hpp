// The CAN link for `kerf sim --link can`: a hal::SegmentLink whose segments
// run on the host's interpolator (hal::CspSegmentLink) and go out once per
// SYNC to simulated CiA 402 drives through the CANopen master. Two buses:
// - in-process (iface empty): a virtual clock, one SYNC per tick(), so a
//   run is repeatable at any speed;
// - SocketCAN (iface "vcan0"...): the kernel's CAN stack, the drives on their
//   own socket on a thread of this process, tick() waits for the wall-clock
//   SYNC. (kerf-drive-sim runs them as a separate process instead.)
// The controller drives it like the Modbus board: push/status/command, and
// tick() where the board's servo tick would be (sync_period_s() each).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "kerf/hal/axis_link.hpp"
#include "kerf/hal/can/csp_segment_link.hpp"
#include "kerf/hal/segment_link.hpp"
#include "machine/can_link.hpp"

namespace kerf::simulated {

enum class CanFaultKind : std::uint8_t { heartbeat_loss, emcy, bus_off, enable_refused, stall };  // stall: the x drive jams
const char* to_string(CanFaultKind k);
// "heartbeat-loss", "emcy", "bus-off", "enable-refused"; false for anything else.
bool parse_can_fault(const std::string& text, CanFaultKind& out);

// The CAN link's options (machine/can_link.hpp; iface empty: the in-process
// bus) and the simulated drives'.
struct CanSimOptions : machine::CanLinkOptions {
  Vec2<double> start{};          // where the axes are at power-up, mm
  // A drive (axis index) that refuses "enable operation" from power-up: the
  // link cannot be made and the error says which drive. -1: none.
  int refuse_enable_axis = -1;
  std::string candump_path;      // candump -L log of every frame ("": none)
  // Home switches (x, y, z), mm in the power-up frame (z powers up at 0):
  // CiA 402 homing (methods 17/18) finds them. No switch: homing runs out of
  // its search distance.
  bool has_home_switch[3] = {false, false, false};
  double home_switch[3] = {0.0, 0.0, 0.0};
};

class CanSimLink : public machine::CanMasterLink {
 public:
  // One SYNC period: the interpolator's setpoint out, the drives' feedback in.
  virtual void tick() = 0;
  virtual double sync_period_s() const = 0;
  // A fault on the bus or a drive, now. heartbeat-loss and enable-refused
  // hit the last axis's drive, emcy the first's. enable-refused: the drive
  // faults (EMCY) and then refuses to be enabled again.
  virtual void inject(CanFaultKind k) = 0;
  hal::CspSegmentLink& csp() { return *csp_; }
  const hal::AxisLink& axes() const { return *master_; }
  // Worst-case bus load of the frames sent so far, bits/s (in-process only; 0 otherwise).
  virtual double bus_load_bps() const = 0;
  // Where the axis's drive last left its home switch, counts in its power-up
  // frame (in-process only; 0 otherwise).
  virtual std::int32_t home_latch(std::size_t axis) const = 0;
  // Writes candump_path (the in-process log; SocketCAN logs as it goes).
  virtual bool finish_log(std::string& error) = 0;
};

// The options a machine configuration gives: axes and their counts/mm,
// link.node_ids, link.sync_ms, machine.accel; the in-process bus (set iface
// for SocketCAN: the config's link.iface names the real machine's bus).
CanSimOptions can_sim_options(const config::Config& cfg);

// Starts the drives, brings them up (NMT, SDO setup) and enables them (402).
// Null with a clear reason in `error` when anything fails.
std::unique_ptr<CanSimLink> make_can_sim_link(const CanSimOptions& opts, std::string& error);

}  // namespace kerf::simulated
