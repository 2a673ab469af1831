// sim::VirtualCanBus: an in-process CAN bus on a virtual clock, connecting
// one master port (a hal::CanBus) with N simulated CiA 402 drives. The same
// frames as on SocketCAN. Time only moves when the master waits for frames
// (receive with a deadline), so every test is deterministic. Every frame is
// logged (candump format on request) for frame-by-frame checks and bus load.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "kerf/hal/can_bus.hpp"
#include "kerf/sim/can/drive_node.hpp"

namespace kerf::sim {

struct LoggedFrame {
  std::uint64_t t_us;
  hal::CanFrame frame;
  bool from_master;
};

class VirtualCanBus {
 public:
  // queue_capacity: frames waiting for the master; a full queue refuses the
  // sender's frame (counted by the sender), never drops one already queued.
  explicit VirtualCanBus(std::size_t queue_capacity = 512);
  ~VirtualCanBus();
  VirtualCanBus(const VirtualCanBus&) = delete;
  VirtualCanBus& operator=(const VirtualCanBus&) = delete;

  hal::CanBus& master();
  // Adds a drive and powers it on (its boot-up message goes out now).
  DriveNode& add_drive(const DriveConfig& cfg);
  DriveNode& drive(std::size_t i) { return *drives_[i]; }
  const DriveNode& drive(std::size_t i) const { return *drives_[i]; }
  std::size_t drive_count() const { return drives_.size(); }

  std::uint64_t now_us() const { return now_us_; }
  // The master's controller goes bus-off (sends refused) until recover().
  void inject_bus_off();
  void recover();
  // A frame from a foreign node, queued for the master.
  void inject_frame(const hal::CanFrame& f);

  const std::vector<LoggedFrame>& log() const { return log_; }
  // candump -L style: "(seconds.micros) iface ID#DATA", one frame a line.
  bool write_candump(const std::string& path, const std::string& iface, std::string& error) const;

 private:
  class MasterPort;
  class DrivePort;
  friend class MasterPort;
  friend class DrivePort;

  hal::CanResult from_master(const hal::CanFrame& f);
  hal::CanResult from_drive(const hal::CanFrame& f);
  void advance_to(std::uint64_t t_us);

  std::size_t capacity_;
  std::uint64_t now_us_ = 0;
  bool bus_off_ = false;
  std::deque<hal::CanFrame> to_master_;
  std::vector<LoggedFrame> log_;
  std::unique_ptr<MasterPort> master_;
  std::vector<std::unique_ptr<DrivePort>> ports_;
  std::vector<std::unique_ptr<DriveNode>> drives_;
};

// One candump line for a frame (no newline).
std::string candump_line(std::uint64_t t_us, const std::string& iface, const hal::CanFrame& f);

}  // namespace kerf::sim
