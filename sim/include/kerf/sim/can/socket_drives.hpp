// sim::SocketDrives: simulated CiA 402 drives served on a SocketCAN
// interface, on their own socket: the same frames the in-process bus carries,
// through the kernel's CAN stack. kerf-drive-sim runs them in its own
// process; `kerf sim --link can --iface vcan0` on a thread. Optionally logs
// every frame seen or sent (candump -L format).
#pragma once

#include <atomic>
#include <cstdint>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "kerf/hal/can/socket_can_bus.hpp"
#include "kerf/sim/can/drive_node.hpp"

namespace kerf::sim {

class SocketDrives {
 public:
  // Null with the reason in `error` (no such interface, no CAN support, log unwritable).
  static std::unique_ptr<SocketDrives> open(const std::string& iface, const std::vector<DriveConfig>& drives,
                                            const std::string& log_path, std::string& error);
  ~SocketDrives();
  SocketDrives(const SocketDrives&) = delete;
  SocketDrives& operator=(const SocketDrives&) = delete;

  // Serves until `stop` is set (or, with idle_exit_us > 0, that long without
  // a frame once SYNC ran). False with `error` on a socket error.
  bool serve(const std::atomic<bool>& stop, std::uint64_t idle_exit_us, std::string& error);
  void start_thread();
  void stop_thread();

  // Injected on the serving thread at the next frame or wake-up; with
  // after_syncs, once that many SYNCs were seen.
  void inject(std::uint8_t node, DriveFault f, std::uint64_t after_syncs = 0);
  std::uint64_t syncs() const { return syncs_.load(); }

 private:
  class LoggingBus;
  SocketDrives() = default;
  void apply_pending(std::uint64_t now_us);

  std::unique_ptr<hal::SocketCanBus> socket_;
  std::unique_ptr<std::ofstream> log_;
  std::unique_ptr<LoggingBus> bus_;
  std::vector<std::unique_ptr<DriveNode>> drives_;
  std::atomic<std::uint64_t> syncs_{0};
  struct Pending {
    std::uint8_t node;
    DriveFault fault;
    std::uint64_t after_syncs;
  };
  std::mutex pending_mu_;
  std::vector<Pending> pending_;
  std::atomic<bool> thread_stop_{false};
  std::thread thread_;
};

}  // namespace kerf::sim
