// The CANopen side of a CAN link: the master (NMT, SDO set-up, CiA 402
// enable) and the CSP link that interpolates segments into one setpoint per
// SYNC. The machine's own drives (open_machine_can_link, `kerf run`) and the
// simulator's (simulated/can_sim_link.hpp) share it; only the bus differs.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "kerf/hal/axis_link.hpp"
#include "kerf/hal/can/canopen_master.hpp"
#include "kerf/hal/can/csp_segment_link.hpp"
#include "kerf/hal/can/socket_can_bus.hpp"
#include "kerf/hal/segment_link.hpp"

namespace kerf::machine {

struct CanLinkOptions {
  std::size_t axes = 2;          // 2 or 3: x, y and z (without z limits the third axis holds its position)
  std::vector<std::uint8_t> node_ids;  // one per axis (the config's link.node_ids); empty: 1..axes
  double sync_ms = 1;            // SYNC period, a whole number of ms in 1..10
  std::string iface;             // SocketCAN interface; the simulator: empty for its in-process bus
  Vec2<double> counts_per_mm{1000.0, 1000.0};  // x, y (a third axis: x's)
  double accel_mm_s2 = 2000.0;
  double vad = 0.9;  // [cut] vad / 100: thc_lock below this fraction of the cut feed
  double corner_angle_rad = 0.05;
  std::size_t queue_slots = 32;
  motion::AxisLimits<double> z{};  // the z axis (config::z_limits): the third drive runs the z moves
  double z_counts_per_mm = 1000.0;
  motion::SoftLimits<double> soft_limits{};  // the executor's second check ([[machine.axis]] min/max)
};

// The options a machine configuration gives: axes and their counts/mm,
// link.node_ids, link.sync_ms, machine.accel (iface is left empty: the
// caller names the bus).
void read_can_link_options(const config::Config& cfg, CanLinkOptions& o);

// The node id of an axis.
std::uint8_t can_node_of(const CanLinkOptions& o, std::size_t axis);
// What the master reads: the drives' EMCY, TPDO1, SDO replies and heartbeats.
std::vector<hal::CanFilter> can_master_filters();

// A SegmentLink over the CANopen master and its CSP link.
class CanMasterLink : public hal::SegmentLink {
 public:
  hal::LinkError push(const hal::SegmentCommand& s, hal::BoardStatus& st) override { return csp_->push(s, st); }
  hal::LinkError status(hal::BoardStatus& st) override { return csp_->status(st); }
  hal::LinkError command(hal::Command c) override { return csp_->command(c); }
  // CiA 402 homing mode on the axis's drive (kerf home).
  hal::LinkError home(const hal::HomeCommand& h, const std::function<bool()>& stop) override {
    return csp_->home(h, stop);
  }
  std::uint64_t resends() const override { return 0; }
  const char* last_error() const override { return csp_->last_error(); }

 protected:
  // Brings the drives up (NMT, SDO set-up) and enables them (402) on `bus`.
  // wall_clock: heartbeat and SDO timeouts a loaded host cannot trip.
  bool start(hal::CanBus& bus, const CanLinkOptions& o, bool wall_clock, std::string& error);
  std::unique_ptr<hal::CanOpenMaster> master_;
  std::unique_ptr<hal::CspSegmentLink> csp_;
};

// The machine's drives for `kerf run`: the CANopen master on the SocketCAN
// interface opts.iface (brought up, enabled), the CSP link's clock on a
// thread of its own. Null with the reason when anything fails.
std::unique_ptr<hal::SegmentLink> open_machine_can_link(const CanLinkOptions& opts, std::string& error);

}  // namespace kerf::machine
