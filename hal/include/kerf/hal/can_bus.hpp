// hal::CanBus: classic CAN frames in and out, and the bus's own clock. Two
// implementations: SocketCAN (hal/can) and sim's in-process bus, which runs
// on a virtual clock so tests are deterministic. The frame is kerf's own POD,
// so this header needs no Linux header.
#pragma once

#include <cstdint>

namespace kerf::hal {

struct CanFrame {
  std::uint32_t id = 0;  // 11-bit identifier (standard frames only)
  std::uint8_t dlc = 0;  // 0..8
  std::uint8_t data[8]{};
};

// The controller's error state as the bus reports it (ISO 11898-1).
enum class BusState : std::uint8_t { active, warning, passive, bus_off };

enum class CanResult : std::uint8_t {
  ok,
  timeout,     // nothing arrived before the deadline
  queue_full,  // the send queue is full: the frame was not sent (never dropped silently)
  bus_off,     // the controller is bus-off: nothing goes out
  io_error,    // the OS refused (see last_error)
};

const char* to_string(CanResult r);
const char* to_string(BusState s);

struct CanCounters {
  std::uint64_t sent = 0;
  std::uint64_t received = 0;
  std::uint64_t error_frames = 0;  // SocketCAN error frames seen
  std::uint64_t send_refused = 0;  // queue_full or bus_off on send
};

class CanBus {
 public:
  virtual ~CanBus() = default;
  virtual CanResult send(const CanFrame& f) = 0;
  // Waits for the next frame until the bus clock reaches `until_us`;
  // timeout when none came. Error frames are consumed here (they change
  // state()), never returned as frames.
  virtual CanResult receive(CanFrame& f, std::uint64_t until_us) = 0;
  virtual std::uint64_t now_us() = 0;
  virtual BusState state() const = 0;
  // Recovery policy after bus-off: true when the controller is back to
  // error-active (SocketCAN: the kernel's restart-ms restarted it).
  virtual bool recovered() = 0;
  virtual const CanCounters& counters() const = 0;
  virtual const char* last_error() const = 0;
};

}  // namespace kerf::hal
