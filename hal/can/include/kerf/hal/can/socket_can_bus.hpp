// hal::SocketCanBus: hal::CanBus over a Linux SocketCAN raw socket. Receive
// filters let through only the CANopen function codes the owner asks for;
// error frames (CAN_RAW_ERR_FILTER) track the controller state: error-
// passive is counted, bus-off refuses every send until the kernel reports
// the controller restarted (its restart-ms policy). Sends never block: a full
// queue (ENOBUFS / EAGAIN) is returned as queue_full, never dropped silently.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "kerf/hal/can_bus.hpp"

namespace kerf::hal {

struct CanFilter {
  std::uint32_t id = 0;
  std::uint32_t mask = 0;  // a frame passes when (frame.id & mask) == (id & mask)
};

class SocketCanBus final : public CanBus {
 public:
  // Opens `iface` (e.g. "vcan0"); no filters: every frame passes. Null with
  // the reason in `error`.
  static std::unique_ptr<SocketCanBus> open(const std::string& iface, const std::vector<CanFilter>& filters,
                                            std::string& error);
  ~SocketCanBus() override;
  SocketCanBus(const SocketCanBus&) = delete;
  SocketCanBus& operator=(const SocketCanBus&) = delete;

  CanResult send(const CanFrame& f) override;
  CanResult receive(CanFrame& f, std::uint64_t until_us) override;
  std::uint64_t now_us() override;  // CLOCK_MONOTONIC
  BusState state() const override { return state_; }
  bool recovered() override;
  const CanCounters& counters() const override { return counters_; }
  const char* last_error() const override { return error_; }

 private:
  explicit SocketCanBus(int fd) : fd_(fd) {}
  void on_error_frame(std::uint32_t id, const std::uint8_t* data);

  int fd_ = -1;
  BusState state_ = BusState::active;
  CanCounters counters_{};
  char error_[160] = "";
};

}  // namespace kerf::hal
