#include "kerf/sim/can/socket_drives.hpp"

#include <algorithm>

#include "kerf/hal/canopen.hpp"
#include "kerf/sim/can/virtual_can_bus.hpp"

namespace kerf::sim {

// Sends through the socket and logs what went out and what came in.
class SocketDrives::LoggingBus final : public hal::CanBus {
 public:
  LoggingBus(hal::CanBus& inner, std::ofstream* log, std::string iface)
      : inner_(inner), log_(log), iface_(std::move(iface)) {}
  hal::CanResult send(const hal::CanFrame& f) override {
    const auto r = inner_.send(f);
    if (r == hal::CanResult::ok) record(f);
    return r;
  }
  hal::CanResult receive(hal::CanFrame& f, std::uint64_t until_us) override {
    const auto r = inner_.receive(f, until_us);
    if (r == hal::CanResult::ok) record(f);
    return r;
  }
  std::uint64_t now_us() override { return inner_.now_us(); }
  hal::BusState state() const override { return inner_.state(); }
  bool recovered() override { return inner_.recovered(); }
  const hal::CanCounters& counters() const override { return inner_.counters(); }
  const char* last_error() const override { return inner_.last_error(); }

 private:
  void record(const hal::CanFrame& f) {
    if (log_ != nullptr) *log_ << candump_line(inner_.now_us(), iface_, f) << '\n';
  }
  hal::CanBus& inner_;
  std::ofstream* log_;
  std::string iface_;
};

std::unique_ptr<SocketDrives> SocketDrives::open(const std::string& iface, const std::vector<DriveConfig>& drives,
                                                 const std::string& log_path, std::string& error) {
  std::unique_ptr<SocketDrives> d(new SocketDrives());
  d->socket_ = hal::SocketCanBus::open(iface, {}, error);
  if (!d->socket_) return nullptr;
  if (!log_path.empty()) {
    d->log_ = std::make_unique<std::ofstream>(log_path);
    if (!*d->log_) {
      error = log_path + ": cannot write the CAN log";
      return nullptr;
    }
  }
  d->bus_ = std::make_unique<LoggingBus>(*d->socket_, d->log_.get(), iface);
  for (const DriveConfig& c : drives) d->drives_.push_back(std::make_unique<DriveNode>(c, *d->bus_));
  return d;
}

SocketDrives::~SocketDrives() { stop_thread(); }

void SocketDrives::inject(std::uint8_t node, DriveFault f, std::uint64_t after_syncs) {
  std::lock_guard<std::mutex> lock(pending_mu_);
  pending_.push_back({node, f, after_syncs});
}

void SocketDrives::apply_pending(std::uint64_t now_us) {
  std::lock_guard<std::mutex> lock(pending_mu_);
  for (std::size_t i = 0; i < pending_.size();) {
    if (syncs_.load() < pending_[i].after_syncs) {
      ++i;
      continue;
    }
    for (auto& d : drives_)
      if (d->node() == pending_[i].node) d->inject(pending_[i].fault, now_us);
    pending_.erase(pending_.begin() + static_cast<long>(i));
  }
}

bool SocketDrives::serve(const std::atomic<bool>& stop, std::uint64_t idle_exit_us, std::string& error) {
  for (auto& d : drives_) d->power_on(bus_->now_us());
  std::uint64_t last_frame_us = bus_->now_us();
  while (!stop.load()) {
    std::uint64_t next = bus_->now_us() + 10000;  // wake at least every 10 ms (stop, injections)
    for (auto& d : drives_) next = std::min(next, std::max(d->next_event_us(), bus_->now_us()));
    hal::CanFrame f;
    const auto r = bus_->receive(f, next);
    const std::uint64_t now = bus_->now_us();
    if (r == hal::CanResult::ok) {
      last_frame_us = now;
      if (f.id == hal::canopen::kSync) ++syncs_;
      apply_pending(now);
      for (auto& d : drives_) d->handle(f, now);
    } else if (r != hal::CanResult::timeout) {
      error = bus_->last_error();
      return false;
    } else {
      apply_pending(now);
    }
    for (auto& d : drives_) d->tick(now);
    if (idle_exit_us > 0 && syncs_.load() > 0 && now - last_frame_us > idle_exit_us) break;
  }
  if (log_) log_->flush();
  return true;
}

void SocketDrives::start_thread() {
  thread_stop_ = false;
  thread_ = std::thread([this] {
    std::string error;
    serve(thread_stop_, 0, error);
  });
}

void SocketDrives::stop_thread() {
  if (!thread_.joinable()) return;
  thread_stop_ = true;
  thread_.join();
}

}  // namespace kerf::sim
