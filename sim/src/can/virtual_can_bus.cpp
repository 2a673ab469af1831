#include "kerf/sim/can/virtual_can_bus.hpp"

#include <cstdio>
#include <fstream>

namespace kerf::sim {

using hal::CanFrame;
using hal::CanResult;

class VirtualCanBus::MasterPort final : public hal::CanBus {
 public:
  explicit MasterPort(VirtualCanBus& bus) : bus_(bus) {}
  CanResult send(const CanFrame& f) override {
    const CanResult r = bus_.from_master(f);
    if (r == CanResult::ok) ++counters_.sent;
    else ++counters_.send_refused;
    return r;
  }
  CanResult receive(CanFrame& f, std::uint64_t until_us) override {
    for (;;) {
      if (!bus_.to_master_.empty()) {
        f = bus_.to_master_.front();
        bus_.to_master_.pop_front();
        ++counters_.received;
        return CanResult::ok;
      }
      if (bus_.now_us_ >= until_us) return CanResult::timeout;
      // Nothing waiting: time moves to the deadline or the next drive event.
      std::uint64_t t = until_us;
      for (const auto& d : bus_.drives_)
        if (d->next_event_us() > bus_.now_us_ && d->next_event_us() < t) t = d->next_event_us();
      bus_.advance_to(t);
    }
  }
  std::uint64_t now_us() override { return bus_.now_us_; }
  hal::BusState state() const override { return bus_.bus_off_ ? hal::BusState::bus_off : hal::BusState::active; }
  bool recovered() override { return !bus_.bus_off_; }
  const hal::CanCounters& counters() const override { return counters_; }
  const char* last_error() const override { return bus_.bus_off_ ? "bus-off (injected)" : "send queue full"; }

 private:
  VirtualCanBus& bus_;
  hal::CanCounters counters_{};
};

class VirtualCanBus::DrivePort final : public hal::CanBus {
 public:
  explicit DrivePort(VirtualCanBus& bus) : bus_(bus) {}
  CanResult send(const CanFrame& f) override {
    const CanResult r = bus_.from_drive(f);
    if (r == CanResult::ok) ++counters_.sent;
    else ++counters_.send_refused;
    return r;
  }
  // Drives are handed their frames by the bus; they never wait for one.
  CanResult receive(CanFrame&, std::uint64_t) override { return CanResult::timeout; }
  std::uint64_t now_us() override { return bus_.now_us_; }
  hal::BusState state() const override { return hal::BusState::active; }
  bool recovered() override { return true; }
  const hal::CanCounters& counters() const override { return counters_; }
  const char* last_error() const override { return "send queue full"; }

 private:
  VirtualCanBus& bus_;
  hal::CanCounters counters_{};
};

VirtualCanBus::VirtualCanBus(std::size_t queue_capacity)
    : capacity_(queue_capacity), master_(std::make_unique<MasterPort>(*this)) {
  log_.reserve(1 << 16);
}

VirtualCanBus::~VirtualCanBus() = default;

hal::CanBus& VirtualCanBus::master() { return *master_; }

DriveNode& VirtualCanBus::add_drive(const DriveConfig& cfg) {
  ports_.push_back(std::make_unique<DrivePort>(*this));
  drives_.push_back(std::make_unique<DriveNode>(cfg, *ports_.back()));
  drives_.back()->power_on(now_us_);
  return *drives_.back();
}

CanResult VirtualCanBus::from_master(const CanFrame& f) {
  if (bus_off_) return CanResult::bus_off;
  log_.push_back({now_us_, f, true});
  // Broadcast: every drive sees every frame and picks its own, as on a wire.
  for (const auto& d : drives_) d->handle(f, now_us_);
  return CanResult::ok;
}

CanResult VirtualCanBus::from_drive(const CanFrame& f) {
  if (to_master_.size() >= capacity_) return CanResult::queue_full;
  log_.push_back({now_us_, f, false});
  to_master_.push_back(f);
  return CanResult::ok;
}

void VirtualCanBus::advance_to(std::uint64_t t_us) {
  now_us_ = t_us;
  for (const auto& d : drives_) d->tick(now_us_);
}

void VirtualCanBus::inject_bus_off() { bus_off_ = true; }
void VirtualCanBus::recover() { bus_off_ = false; }

void VirtualCanBus::inject_frame(const CanFrame& f) {
  log_.push_back({now_us_, f, false});
  to_master_.push_back(f);
}

std::string candump_line(std::uint64_t t_us, const std::string& iface, const CanFrame& f) {
  char buf[96];
  int n = std::snprintf(buf, sizeof buf, "(%llu.%06llu) %s %03X#", static_cast<unsigned long long>(t_us / 1000000u),
                        static_cast<unsigned long long>(t_us % 1000000u), iface.c_str(),
                        static_cast<unsigned>(f.id));
  for (int i = 0; i < f.dlc && i < 8 && n > 0 && n < static_cast<int>(sizeof buf) - 3; ++i)
    n += std::snprintf(buf + n, sizeof buf - static_cast<std::size_t>(n), "%02X", f.data[i]);
  return buf;
}

bool VirtualCanBus::write_candump(const std::string& path, const std::string& iface, std::string& error) const {
  std::ofstream out(path);
  for (const LoggedFrame& l : log_) out << candump_line(l.t_us, iface, l.frame) << '\n';
  out.flush();
  if (!out) {
    error = path + ": cannot write the CAN log";
    return false;
  }
  return true;
}

}  // namespace kerf::sim
