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

namespace kerf::simulated {

enum class CanFaultKind : std::uint8_t { heartbeat_loss, emcy, bus_off, enable_refused, stall };  // stall: the x drive jams
const char* to_string(CanFaultKind k);
// "heartbeat-loss", "emcy", "bus-off", "enable-refused"; false for anything else.
bool parse_can_fault(const std::string& text, CanFaultKind& out);

struct CanSimOptions {
  std::size_t axes = 2;          // 2 or 3: x, y (and a third axis that holds its position)
  std::vector<std::uint8_t> node_ids;  // one per axis (the config's link.node_ids); empty: 1..axes
  double sync_ms = 1;            // SYNC period, a whole number of ms in 1..10
  std::string iface;             // empty: the in-process bus
  Vec2<double> start{};          // where the axes are at power-up, mm
  Vec2<double> counts_per_mm{1000.0, 1000.0};  // x, y (a third axis: x's)
  double accel_mm_s2 = 2000.0;
  double corner_angle_rad = 0.05;
  std::size_t queue_slots = 32;
  // A drive (axis index) that refuses "enable operation" from power-up: the
  // link cannot be made and the error says which drive. -1: none.
  int refuse_enable_axis = -1;
  std::string candump_path;      // candump -L log of every frame ("": none)
};

class CanSimLink : public hal::SegmentLink {
 public:
  // One SYNC period: the interpolator's setpoint out, the drives' feedback in.
  virtual void tick() = 0;
  virtual double sync_period_s() const = 0;
  // A fault on the bus or a drive, now. heartbeat-loss and enable-refused
  // hit the last axis's drive, emcy the first's. enable-refused: the drive
  // faults (EMCY) and then refuses to be enabled again.
  virtual void inject(CanFaultKind k) = 0;
  virtual hal::CspSegmentLink& csp() = 0;
  virtual const hal::AxisLink& axes() const = 0;
  // Worst-case bus load of the frames sent so far, bits/s (in-process only; 0 otherwise).
  virtual double bus_load_bps() const = 0;
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

// The machine's drives for `kerf run`: the CANopen master on the SocketCAN
// interface opts.iface (brought up, enabled), the CSP link's clock on a
// thread of its own. Null with the reason when anything fails.
std::unique_ptr<hal::SegmentLink> open_machine_can_link(const CanSimOptions& opts, std::string& error);

}  // namespace kerf::simulated
