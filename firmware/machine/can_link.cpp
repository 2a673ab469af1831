#include "machine/can_link.hpp"

#include <cmath>

#include "kerf/hal/can/socket_can_bus.hpp"
#include "control/soft_limits.hpp"
#include "kerf/hal/canopen.hpp"

namespace kerf::machine {

namespace {

hal::CanOpenConfig master_config(const CanLinkOptions& o, bool wall_clock) {
  hal::CanOpenConfig c;
  c.nodes.clear();
  for (std::size_t i = 0; i < o.axes; ++i) c.nodes.push_back(can_node_of(o, i));
  c.sync_us = static_cast<std::uint32_t>(std::lround(o.sync_ms * 1000.0));
  if (wall_clock) {  // a loaded host must not look like a dead drive
    c.heartbeat_ms = 50;
    c.heartbeat_timeout_ms = 250;
    c.sdo_timeout_us = 500000;
    c.boot_timeout_us = 2000000;
    c.homing_lead_syncs = 5;  // drives' TPDOs a few SYNCs late (seen on vcan0: one more than the in-process 2)
  }
  return c;
}

// The machine's own drives on a SocketCAN interface: the CSP clock runs on
// its own thread, paced by the SYNC on the wall clock, so the controller's
// cycle only queues and polls.
class MachineCanLink final : public CanMasterLink {
 public:
  ~MachineCanLink() override {
    if (csp_) csp_->stop_clock();
  }
  bool open(const CanLinkOptions& o, std::string& error) {
    bus_ = hal::SocketCanBus::open(o.iface, can_master_filters(), error);
    if (!bus_ || !start(*bus_, o, true, error)) return false;
    csp_->run_clock(true);
    return true;
  }

 private:
  std::unique_ptr<hal::SocketCanBus> bus_;
};

}  // namespace

void read_can_link_options(const config::Config& cfg, CanLinkOptions& o) {
  o.axes = cfg.machine.axes.size();
  o.node_ids.clear();
  for (int id : cfg.link.node_ids) o.node_ids.push_back(static_cast<std::uint8_t>(id));
  o.sync_ms = cfg.link.sync_ms;
  if (!cfg.machine.axes.empty()) o.counts_per_mm.x = cfg.machine.axes[0].counts_per_mm;
  if (cfg.machine.axes.size() > 1) o.counts_per_mm.y = cfg.machine.axes[1].counts_per_mm;
  o.accel_mm_s2 = cfg.machine.accel;
  o.vad = cfg.cut.rules.vad / 100.0;
  o.z = config::z_limits(cfg.machine);
  if (cfg.machine.axes.size() > 2) o.z_counts_per_mm = cfg.machine.axes[2].counts_per_mm;
  o.soft_limits = control::soft_limits_of(cfg.machine);
}

std::uint8_t can_node_of(const CanLinkOptions& o, std::size_t axis) {
  return o.node_ids.empty() ? static_cast<std::uint8_t>(axis + 1) : o.node_ids[axis];
}

std::vector<hal::CanFilter> can_master_filters() {
  return {{hal::canopen::kEmcy, 0x780},
          {hal::canopen::kTpdo1, 0x780},
          {hal::canopen::kSdoTx, 0x780},
          {hal::canopen::kHeartbeat, 0x780}};
}

bool CanMasterLink::start(hal::CanBus& bus, const CanLinkOptions& o, bool wall_clock, std::string& error) {
  master_ = hal::CanOpenMaster::create(bus, master_config(o, wall_clock), error);
  if (!master_) return false;
  if (master_->bring_up() != hal::AxisError::none) {
    error = std::string("CAN bring-up: ") + master_->last_error();
    return false;
  }
  // Homed since the drives' power-up (kerf run checks it against the state
  // file). A drive without homing mode refuses mode 6 (SDO abort): not homed.
  std::uint8_t homed = 0;
  for (std::size_t a = 0; a < o.axes && a < 3; ++a) {  // z too: the third node
    bool h = false;
    const hal::AxisError e = master_->homed_since_power_up(a, h);
    if (e != hal::AxisError::none && e != hal::AxisError::sdo_abort) {
      error = std::string("CAN bring-up: reading the homed state: ") + master_->last_error();
      return false;
    }
    if (h) homed = static_cast<std::uint8_t>(homed | (1u << a));
  }
  if (master_->enable() != hal::AxisError::none) {
    error = std::string("CAN bring-up: ") + master_->last_error();
    return false;
  }
  hal::CspConfig c;
  c.counts_per_mm = o.counts_per_mm;
  c.accel_mm_s2 = o.accel_mm_s2;
  c.vad = o.vad;
  c.corner_angle_rad = o.corner_angle_rad;
  c.queue_slots = o.queue_slots;
  c.soft_limits = o.soft_limits;
  if (o.axes > 2) {  // z: the third node
    c.z = o.z;
    c.z_counts_per_mm = o.z_counts_per_mm;
  }
  csp_ = hal::CspSegmentLink::create(*master_, c, error);
  if (csp_) csp_->set_homed(homed);
  return csp_ != nullptr;
}

std::unique_ptr<hal::SegmentLink> open_machine_can_link(const CanLinkOptions& opts, std::string& error) {
  if (opts.iface.empty()) {
    error = "link.iface: kerf run needs a SocketCAN interface (can0, vcan0 ...)";
    return nullptr;
  }
  auto link = std::make_unique<MachineCanLink>();
  if (!link->open(opts, error)) return nullptr;
  return link;
}

}  // namespace kerf::machine
