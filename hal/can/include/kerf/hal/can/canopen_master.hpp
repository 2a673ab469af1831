// hal::CanOpenMaster: a CANopen master subset driving N CiA 402 drives in
// Cyclic Synchronous Position mode over any hal::CanBus. Bring-up: NMT
// reset, expedited SDO setup, NMT start; cyclic: RPDO1 (controlword, target
// position) to every drive, then SYNC; TPDO1 (statusword, actual position)
// back. Heartbeat consumer and EMCY. Frames that do not fit (wrong DLC, a
// COB-ID of no configured node, an SDO reply nobody asked for) are counted
// and ignored, never trusted.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "kerf/hal/axis_link.hpp"
#include "kerf/hal/can_bus.hpp"

namespace kerf::hal {

struct CanOpenConfig {
  std::vector<std::uint8_t> nodes{1, 2};  // node ids 1..127, one per axis
  std::uint32_t sync_us = 1000;           // SYNC period, 1..10 ms
  std::uint16_t heartbeat_ms = 20;        // the drives' producer time (0x1017)
  std::uint16_t heartbeat_timeout_ms = 60;  // consumer: a drive silent this long is lost
  std::uint32_t sdo_timeout_us = 50000;
  std::uint32_t boot_timeout_us = 500000;  // reset node -> boot-up heartbeat
  std::uint32_t enable_cycles = 50;        // per 402 transition
  // A homing search is halted this many SYNCs' travel before its search
  // distance: the feedback's age plus the halt's own period. 2 where the
  // feedback is one SYNC old (the in-process bus); more on a real bus, where
  // a drive's TPDO can come a SYNC or more late.
  std::uint32_t homing_lead_syncs = 2;
};

class CanOpenMaster final : public AxisLink {
 public:
  // Null with the reason in `error` for a bad configuration.
  static std::unique_ptr<CanOpenMaster> create(CanBus& bus, const CanOpenConfig& cfg,
                                               std::string& error);

  std::size_t axis_count() const override { return nodes_.size(); }
  double period_s() const override { return static_cast<double>(cfg_.sync_us) * 1e-6; }
  AxisError bring_up() override;
  AxisError enable() override;
  AxisError disable() override;
  AxisError fault_reset() override;
  void set_target(std::size_t axis, std::int32_t counts) override { nodes_[axis].st.target = counts; }
  AxisError cycle() override;
  const AxisState& axis(std::size_t i) const override { return nodes_[i].st; }
  const AxisCounters& counters() const override { return counters_; }
  const char* last_error() const override { return error_; }

  // Homes one enabled axis in CiA 402 homing mode: the method, speeds and
  // offset by SDO, mode 6, controlword bit 4; each SYNC the statusword is
  // watched (bit 12 attained, bit 13 error) and the travel against
  // max_travel; `stop` (the E-stop) halts it (bit 8). Back in CSP after,
  // with the target at the drive's new position. The error is a link error;
  // `result` says how homing ended.
  AxisError home(std::size_t axis, const DriveHoming& h, DriveHomingResult& result,
                 const std::function<bool()>& stop) override;

  // Whether the axis's drive has been homed since its power-up: mode 6 for
  // one SDO read of the statusword (bit 12, homing attained), then CSP again.
  // Before enable(): nothing moves. sdo_abort: the drive has no homing mode
  // (or refused the read); its mode is CSP again either way.
  AxisError homed_since_power_up(std::size_t axis, bool& homed);

  // Expedited SDO, exposed for setup beyond the standard set and for tests.
  AxisError sdo_write(std::size_t axis, std::uint16_t index, std::uint8_t sub, std::uint32_t value,
                      std::uint8_t size);
  AxisError sdo_read(std::size_t axis, std::uint16_t index, std::uint8_t sub, std::uint32_t& value);

 private:
  struct Node {
    AxisState st;
    std::uint64_t last_heartbeat_us = 0;
    std::uint8_t nmt_state = 0xFF;  // from the heartbeat; 0xFF: none seen
    bool booted = false;            // boot-up message seen since the reset
    bool sdo_waiting = false;
    bool sdo_done = false;
    CanFrame sdo_request{};
    CanFrame sdo_reply{};
    bool emcy_new = false;
  };

  CanOpenMaster(CanBus& bus, const CanOpenConfig& cfg);
  AxisError send(const CanFrame& f);
  AxisError nmt(std::uint8_t command, std::uint8_t node);
  AxisError sdo(std::size_t axis, const CanFrame& request, CanFrame& reply);
  AxisError setup_node(std::size_t axis);
  // Receives and dispatches frames until the bus clock reaches `until_us`,
  // or (when `stop` is set) until stop() holds.
  template <class Stop>
  AxisError pump(std::uint64_t until_us, Stop stop);
  void dispatch(const CanFrame& f);
  AxisError health();
  AxisError transition(std::uint16_t controlword, int target_state, const char* step);
  AxisError fail(AxisError e, std::size_t axis, const char* what);
  AxisError homing_cycles(std::size_t axis, const DriveHoming& h, DriveHomingResult& result,
                          const std::function<bool()>& stop);

  CanBus& bus_;
  CanOpenConfig cfg_;
  std::vector<Node> nodes_;
  AxisCounters counters_{};
  bool operational_ = false;  // NMT started: heartbeats are watched, SYNC runs
  bool enabled_ = false;      // 402 operation enabled: the statusword is watched
  bool faulted_ = false;      // an error was reported; no new ones until fault_reset
  BusState last_bus_ = BusState::active;
  std::uint64_t next_sync_us_ = 0;
  char error_[200] = "";
};

}  // namespace kerf::hal
