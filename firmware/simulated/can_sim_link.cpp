#include "simulated/can_sim_link.hpp"

#include <cmath>
#include <vector>

#include "kerf/hal/can/canopen_master.hpp"
#include "kerf/hal/can/socket_can_bus.hpp"
#include "kerf/hal/canopen.hpp"
#include "kerf/sim/can/socket_drives.hpp"
#include "kerf/sim/can/virtual_can_bus.hpp"

#include <linux/can.h>
#include <linux/can/error.h>
#include <net/if.h>
#include <sys/socket.h>
#include <unistd.h>

namespace kerf::simulated {

const char* to_string(CanFaultKind k) {
  switch (k) {
    case CanFaultKind::heartbeat_loss: return "heartbeat-loss";
    case CanFaultKind::emcy: return "emcy";
    case CanFaultKind::bus_off: return "bus-off";
    case CanFaultKind::enable_refused: return "enable-refused";
    case CanFaultKind::stall: return "stall";
  }
  return "?";
}

bool parse_can_fault(const std::string& text, CanFaultKind& out) {
  for (CanFaultKind k : {CanFaultKind::heartbeat_loss, CanFaultKind::emcy, CanFaultKind::bus_off,
                         CanFaultKind::enable_refused})
    if (text == to_string(k)) {
      out = k;
      return true;
    }
  return false;
}

namespace {

std::vector<sim::DriveConfig> drive_configs(const CanSimOptions& o) {
  std::vector<sim::DriveConfig> v;
  for (std::size_t i = 0; i < o.axes; ++i) {
    sim::DriveConfig d;
    d.node = machine::can_node_of(o, i);
    const double mm = i == 0 ? o.start.x : i == 1 ? o.start.y : 0.0;
    const double cpm = i == 0 ? o.counts_per_mm.x : i == 1 ? o.counts_per_mm.y : o.z_counts_per_mm;
    d.start = static_cast<std::int32_t>(std::lround(mm * cpm));
    if (i < 3 && o.has_home_switch[i]) {
      d.has_home_switch = true;
      d.home_switch = static_cast<std::int32_t>(std::lround(o.home_switch[i] * cpm));
    }
    v.push_back(d);
  }
  return v;
}

// Shared by both buses: the SYNC period's clock.
class CanSimLinkBase : public CanSimLink {
 public:
  void tick() override { csp_->cycle(); }
  double sync_period_s() const override { return master_->period_s(); }
};

class VirtualCanSimLink final : public CanSimLinkBase {
 public:
  bool open(const CanSimOptions& o, std::string& error) {
    opts_ = o;
    for (const sim::DriveConfig& d : drive_configs(o)) bus_.add_drive(d);
    if (o.refuse_enable_axis >= 0)
      bus_.drive(static_cast<std::size_t>(o.refuse_enable_axis)).inject(sim::DriveFault::enable_refused, 0);
    return start(bus_.master(), o, false, error);
  }
  void inject(CanFaultKind k) override {
    const std::uint64_t now = bus_.now_us();
    sim::DriveNode& last = bus_.drive(bus_.drive_count() - 1);
    switch (k) {
      case CanFaultKind::heartbeat_loss: last.inject(sim::DriveFault::heartbeat_loss, now); break;
      case CanFaultKind::emcy: bus_.drive(0).inject(sim::DriveFault::emcy, now); break;
      case CanFaultKind::bus_off: bus_.inject_bus_off(); break;
      case CanFaultKind::enable_refused:
        last.inject(sim::DriveFault::emcy, now);
        last.inject(sim::DriveFault::enable_refused, now);
        break;
      case CanFaultKind::stall: bus_.drive(0).inject(sim::DriveFault::stall, now); break;
    }
  }
  double bus_load_bps() const override {
    const auto& log = bus_.log();
    if (log.size() < 2 || log.back().t_us == log.front().t_us) return 0.0;
    std::uint64_t bits = 0;
    for (const auto& l : log) bits += hal::canopen::worst_case_bits(l.frame.dlc);
    return static_cast<double>(bits) / (static_cast<double>(log.back().t_us - log.front().t_us) * 1e-6);
  }
  std::int32_t home_latch(std::size_t axis) const override { return bus_.drive(axis).last_latch(); }
  bool finish_log(std::string& error) override {
    return opts_.candump_path.empty() || bus_.write_candump(opts_.candump_path, "vcan-sim", error);
  }

 private:
  sim::VirtualCanBus bus_;
  CanSimOptions opts_;
};

class SocketCanSimLink final : public CanSimLinkBase {
 public:
  ~SocketCanSimLink() override {
    if (drives_) drives_->stop_thread();
  }
  bool open(const CanSimOptions& o, std::string& error) {
    iface_ = o.iface;
    drives_ = sim::SocketDrives::open(o.iface, drive_configs(o), o.candump_path, error);
    if (!drives_) return false;
    if (o.refuse_enable_axis >= 0)
      drives_->inject(machine::can_node_of(o, static_cast<std::size_t>(o.refuse_enable_axis)), sim::DriveFault::enable_refused);
    bus_ = hal::SocketCanBus::open(o.iface, machine::can_master_filters(), error);
    if (!bus_) return false;
    first_ = machine::can_node_of(o, 0);
    last_ = machine::can_node_of(o, o.axes - 1);
    drives_->start_thread();
    return start(*bus_, o, true, error);
  }
  void inject(CanFaultKind k) override {
    switch (k) {
      case CanFaultKind::heartbeat_loss: drives_->inject(last_, sim::DriveFault::heartbeat_loss); break;
      case CanFaultKind::emcy: drives_->inject(first_, sim::DriveFault::emcy); break;
      case CanFaultKind::enable_refused:
        drives_->inject(last_, sim::DriveFault::emcy);
        drives_->inject(last_, sim::DriveFault::enable_refused);
        break;
      case CanFaultKind::bus_off: send_bus_off_error_frame(); break;
      case CanFaultKind::stall: drives_->inject(first_, sim::DriveFault::stall); break;
    }
  }
  double bus_load_bps() const override { return 0.0; }
  std::int32_t home_latch(std::size_t) const override { return 0; }
  bool finish_log(std::string&) override { return true; }

 private:
  // What a CAN controller's driver reports on bus-off; vcan passes it to
  // every socket that asked for error frames.
  void send_bus_off_error_frame() const {
    const int s = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
    if (s < 0) return;
    sockaddr_can addr{};
    addr.can_family = AF_CAN;
    addr.can_ifindex = static_cast<int>(::if_nametoindex(iface_.c_str()));
    can_frame e{};
    e.can_id = CAN_ERR_FLAG | CAN_ERR_BUSOFF;
    e.can_dlc = CAN_ERR_DLC;
    if (::bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0) (void)!::write(s, &e, sizeof e);
    ::close(s);
  }
  std::string iface_;
  std::uint8_t first_ = 1, last_ = 2;  // node ids of the first and last axis
  std::unique_ptr<sim::SocketDrives> drives_;
  std::unique_ptr<hal::SocketCanBus> bus_;
};

}  // namespace

CanSimOptions can_sim_options(const config::Config& cfg) {
  CanSimOptions o;
  machine::read_can_link_options(cfg, o);
  return o;
}

std::unique_ptr<CanSimLink> make_can_sim_link(const CanSimOptions& opts, std::string& error) {
  if (opts.axes < 2 || opts.axes > 3) {
    error = "--axes: the CAN link drives 2 or 3 axes";
    return nullptr;
  }
  if (!(opts.sync_ms >= 1 && opts.sync_ms <= 10) || opts.sync_ms != std::floor(opts.sync_ms)) {
    error = "--sync-ms: the SYNC period must be a whole number of ms in 1..10";
    return nullptr;
  }
  if (!opts.node_ids.empty() && opts.node_ids.size() != opts.axes) {
    error = "link.node_ids: one node id per axis (" + std::to_string(opts.axes) + " axes, " +
            std::to_string(opts.node_ids.size()) + " ids)";
    return nullptr;
  }
  if (opts.refuse_enable_axis >= static_cast<int>(opts.axes)) {
    error = "refuse_enable_axis: no such axis";
    return nullptr;
  }
  if (opts.iface.empty()) {
    auto l = std::make_unique<VirtualCanSimLink>();
    if (!l->open(opts, error)) return nullptr;
    return l;
  }
  auto l = std::make_unique<SocketCanSimLink>();
  if (!l->open(opts, error)) return nullptr;
  return l;
}

}  // namespace kerf::simulated
