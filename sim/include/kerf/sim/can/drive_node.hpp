// sim::DriveNode: a simulated CiA 402 servo drive on CANopen. Object-
// dictionary subset, expedited SDO server, NMT slave, PDO mapping as the
// master writes it, SYNC-driven Cyclic Synchronous Position, the statusword
// state machine, a heartbeat producer, EMCY on faults. The plant follows the
// target of the previous SYNC through a first-order lag (alpha = 1: exactly
// one period behind); the following error is checked against 0x6065.
// Bus-agnostic: frames come in through handle(), go out through the CanBus
// given at construction (the in-process bus or SocketCAN).
#pragma once

#include <cstdint>

#include "kerf/hal/can_bus.hpp"
#include "kerf/hal/canopen.hpp"

namespace kerf::sim {

struct DriveConfig {
  std::uint8_t node = 1;
  std::int32_t start = 0;            // actual position at power-up, counts
  double lag_alpha = 1.0;            // plant: fraction of the command error closed per SYNC (0, 1]
  std::uint32_t following_window = 5000;  // 0x6065 default, counts
  bool has_home_switch = false;      // homing mode (6) searches for it
  std::int32_t home_switch = 0;      // counts, in the power-up frame
};

// Faults injected through the API (never through magic values on the bus).
enum class DriveFault : std::uint8_t {
  none,
  heartbeat_loss,  // the node goes silent: no heartbeat, no PDO, no SDO reply
  emcy,            // an internal fault: EMCY 0x2310 (overcurrent) and state fault
  enable_refused,  // "enable operation" is ignored: the drive stays switched on
  stall,           // the axis jams: the actual position (0x6064) stops, the drive stays enabled
};

struct DriveCounters {
  std::uint64_t syncs = 0;
  std::uint64_t rpdos = 0;
  std::uint64_t bad_dlc = 0;       // frames for this node with the wrong length, refused
  std::uint64_t sdo_aborts = 0;    // aborts this node sent
  std::uint64_t send_refused = 0;  // the bus refused a frame this node sent
};

class DriveNode {
 public:
  DriveNode(const DriveConfig& cfg, hal::CanBus& out);

  void power_on(std::uint64_t now_us);  // boot-up message, pre-operational
  void handle(const hal::CanFrame& f, std::uint64_t now_us);
  void tick(std::uint64_t now_us);  // the heartbeat producer
  std::uint64_t next_event_us() const;
  void inject(DriveFault f, std::uint64_t now_us);

  std::uint8_t node() const { return cfg_.node; }
  std::uint8_t nmt_state() const { return nmt_; }
  std::uint16_t statusword() const;
  hal::canopen::DriveState state() const { return state_; }
  std::int32_t actual() const { return actual_; }
  std::int32_t target() const { return target_; }
  const DriveCounters& counters() const { return counters_; }
  // Where homing's switch released, in the power-up frame (tests).
  std::int32_t last_latch() const { return latched_; }

 private:
  struct Entry {
    std::uint16_t index;
    std::uint8_t sub;
    std::uint8_t size;  // bytes
    bool writable;
    std::uint32_t value;
  };
  static constexpr int kEntries = 28;

  void reset_node(std::uint64_t now_us, bool announce);
  Entry* find(std::uint16_t index, std::uint8_t sub);
  std::uint32_t od(std::uint16_t index, std::uint8_t sub) const;
  void send(const hal::CanFrame& f);
  void on_nmt(const hal::CanFrame& f, std::uint64_t now_us);
  void on_sdo(const hal::CanFrame& f);
  void sdo_abort(const hal::CanFrame& req, std::uint32_t code);
  std::uint32_t check_write(const Entry& e, std::uint32_t value) const;
  void on_rpdo(const hal::CanFrame& f);
  void on_sync();
  void apply_controlword(std::uint16_t cw);
  void enter_fault(std::uint16_t code);
  void send_emcy(std::uint16_t code);
  void send_tpdo();
  void homing_step();  // one SYNC of homing mode
  bool switch_tripped() const;

  DriveConfig cfg_;
  hal::CanBus& out_;
  Entry od_[kEntries]{};
  int od_count_ = 0;
  std::uint8_t nmt_ = hal::canopen::kHbBootUp;
  hal::canopen::DriveState state_ = hal::canopen::DriveState::switch_on_disabled;
  std::uint16_t last_cw_ = 0;
  std::uint16_t pending_cw_ = 0;
  std::int32_t pending_target_ = 0;
  bool pending_ = false;  // an RPDO arrived since the last SYNC
  std::int32_t target_ = 0;
  std::int32_t command_ = 0;  // the target of the previous SYNC: the plant follows it
  std::int32_t actual_ = 0;
  double actual_exact_ = 0.0;
  bool following_error_ = false;
  DriveFault injected_ = DriveFault::none;
  std::uint64_t next_heartbeat_us_ = 0;
  DriveCounters counters_{};
  enum class Homing : std::uint8_t { idle, search, release, attained, halted };
  Homing homing_ = Homing::idle;
  // Homed since power-up: survives mode changes and NMT reset (the position
  // counter does too); in homing mode the statusword's bit 12 reports it.
  bool referenced_ = false;
  std::int32_t latched_ = 0;
};

}  // namespace kerf::sim
