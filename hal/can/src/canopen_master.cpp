#include "kerf/hal/can/canopen_master.hpp"

#include <cstdio>

#include "kerf/hal/canopen.hpp"

namespace kerf::hal {

using namespace canopen;

const char* to_string(AxisError e) {
  switch (e) {
    case AxisError::none: return "none";
    case AxisError::timeout: return "timeout";
    case AxisError::sdo_abort: return "SDO abort";
    case AxisError::enable_refused: return "enable refused";
    case AxisError::drive_fault: return "drive fault";
    case AxisError::heartbeat_lost: return "heartbeat lost";
    case AxisError::emcy: return "emergency";
    case AxisError::bus_off: return "bus-off";
    case AxisError::send_failed: return "send failed";
    case AxisError::not_enabled: return "not enabled";
  }
  return "?";
}

const char* canopen::to_string(DriveState s) {
  switch (s) {
    case DriveState::not_ready: return "not ready to switch on";
    case DriveState::switch_on_disabled: return "switch on disabled";
    case DriveState::ready_to_switch_on: return "ready to switch on";
    case DriveState::switched_on: return "switched on";
    case DriveState::operation_enabled: return "operation enabled";
    case DriveState::quick_stop_active: return "quick stop active";
    case DriveState::fault_reaction_active: return "fault reaction active";
    case DriveState::fault: return "fault";
  }
  return "?";
}

std::unique_ptr<CanOpenMaster> CanOpenMaster::create(CanBus& bus, const CanOpenConfig& cfg,
                                                     std::string& error) {
  if (cfg.nodes.empty()) {
    error = "CANopen: no drive nodes configured";
    return nullptr;
  }
  for (std::size_t i = 0; i < cfg.nodes.size(); ++i) {
    if (cfg.nodes[i] < 1 || cfg.nodes[i] > 127) {
      error = "CANopen: node id " + std::to_string(cfg.nodes[i]) + " is outside 1..127";
      return nullptr;
    }
    for (std::size_t j = 0; j < i; ++j)
      if (cfg.nodes[j] == cfg.nodes[i]) {
        error = "CANopen: node id " + std::to_string(cfg.nodes[i]) + " is used twice";
        return nullptr;
      }
  }
  if (cfg.sync_us < 1000 || cfg.sync_us > 10000 || cfg.sync_us % 1000 != 0) {
    error = "CANopen: the SYNC period must be a whole number of ms in 1..10";
    return nullptr;
  }
  if (cfg.heartbeat_ms == 0 || cfg.heartbeat_timeout_ms <= cfg.heartbeat_ms) {
    error = "CANopen: the heartbeat timeout must exceed the heartbeat period";
    return nullptr;
  }
  return std::unique_ptr<CanOpenMaster>(new CanOpenMaster(bus, cfg));
}

CanOpenMaster::CanOpenMaster(CanBus& bus, const CanOpenConfig& cfg)
    : bus_(bus), cfg_(cfg), nodes_(cfg.nodes.size()) {
  for (std::size_t i = 0; i < nodes_.size(); ++i) nodes_[i].st.node = cfg.nodes[i];
}

AxisError CanOpenMaster::fail(AxisError e, std::size_t axis, const char* what) {
  if (axis < nodes_.size())
    std::snprintf(error_, sizeof error_, "axis %zu (node %u): %s: %s", axis,
                  static_cast<unsigned>(nodes_[axis].st.node), to_string(e), what);
  else
    std::snprintf(error_, sizeof error_, "CAN bus: %s: %s", to_string(e), what);
  return e;
}

AxisError CanOpenMaster::send(const CanFrame& f) {
  switch (bus_.send(f)) {
    case CanResult::ok: return AxisError::none;
    case CanResult::bus_off: return fail(AxisError::bus_off, SIZE_MAX, "the controller is bus-off");
    case CanResult::queue_full: return fail(AxisError::send_failed, SIZE_MAX, "the send queue is full");
    default: return fail(AxisError::send_failed, SIZE_MAX, bus_.last_error());
  }
}

AxisError CanOpenMaster::nmt(std::uint8_t command, std::uint8_t node) {
  CanFrame f;
  f.id = kNmt;
  f.dlc = 2;
  f.data[0] = command;
  f.data[1] = node;
  return send(f);
}

void CanOpenMaster::dispatch(const CanFrame& f) {
  const std::uint32_t fn = f.id & 0x780;
  const std::uint32_t id = f.id & 0x7F;
  Node* n = nullptr;
  std::size_t axis = 0;
  for (; axis < nodes_.size(); ++axis)
    if (nodes_[axis].st.node == id) {
      n = &nodes_[axis];
      break;
    }
  const bool known_fn = fn == kTpdo1 || fn == kEmcy || fn == kSdoTx || fn == kHeartbeat;
  if (n == nullptr || !known_fn || id == 0) {
    ++counters_.unknown_cob;
    return;
  }
  if (fn == kTpdo1) {
    if (f.dlc != 6) {
      ++counters_.bad_dlc;
      return;
    }
    n->st.statusword = get_u16(f.data);
    n->st.actual = static_cast<std::int32_t>(get_u32(f.data + 2));
    n->st.feedback_cycle = counters_.cycles;
  } else if (fn == kHeartbeat) {
    if (f.dlc != 1) {
      ++counters_.bad_dlc;
      return;
    }
    n->nmt_state = f.data[0] & 0x7F;
    n->last_heartbeat_us = bus_.now_us();
    if (n->nmt_state == kHbBootUp) n->booted = true;
  } else if (fn == kEmcy) {
    if (f.dlc != 8) {
      ++counters_.bad_dlc;
      return;
    }
    ++counters_.emcy;
    n->st.emcy_code = get_u16(f.data);
    // Error code 0 is "error reset / no error": the drive clearing its EMCY.
    n->emcy_new = n->st.emcy_code != 0;
  } else {  // SDO reply: only the one we are waiting for, for the same object
    if (f.dlc != 8) {
      ++counters_.bad_dlc;
      return;
    }
    const bool same_object = f.data[1] == n->sdo_request.data[1] &&
                             f.data[2] == n->sdo_request.data[2] &&
                             f.data[3] == n->sdo_request.data[3];
    if (!n->sdo_waiting || !same_object) {
      ++counters_.stray_sdo;
      return;
    }
    n->sdo_reply = f;
    n->sdo_waiting = false;
    n->sdo_done = true;
  }
}

template <class Stop>
AxisError CanOpenMaster::pump(std::uint64_t until_us, Stop stop) {
  CanFrame f;
  while (!stop()) {
    const CanResult r = bus_.receive(f, until_us);
    if (r == CanResult::timeout) return AxisError::none;
    if (r == CanResult::ok) {
      dispatch(f);
      continue;
    }
    if (r == CanResult::bus_off) return fail(AxisError::bus_off, SIZE_MAX, "the controller is bus-off");
    return fail(AxisError::send_failed, SIZE_MAX, bus_.last_error());
  }
  return AxisError::none;
}

AxisError CanOpenMaster::sdo(std::size_t axis, const CanFrame& request, CanFrame& reply) {
  Node& n = nodes_[axis];
  n.sdo_request = request;
  n.sdo_waiting = true;
  n.sdo_done = false;
  if (const AxisError e = send(request); e != AxisError::none) return e;
  const std::uint64_t deadline = bus_.now_us() + cfg_.sdo_timeout_us;
  if (const AxisError e = pump(deadline, [&] { return n.sdo_done; }); e != AxisError::none) return e;
  if (!n.sdo_done) {
    n.sdo_waiting = false;
    char what[80];
    std::snprintf(what, sizeof what, "no SDO reply for 0x%04X:%u", get_u16(request.data + 1),
                  request.data[3]);
    return fail(AxisError::timeout, axis, what);
  }
  reply = n.sdo_reply;
  if (reply.data[0] == kSdoAbort) {
    ++counters_.sdo_aborts;
    char what[80];
    std::snprintf(what, sizeof what, "0x%04X:%u aborted with code 0x%08X", get_u16(request.data + 1),
                  request.data[3], static_cast<unsigned>(get_u32(reply.data + 4)));
    return fail(AxisError::sdo_abort, axis, what);
  }
  return AxisError::none;
}

AxisError CanOpenMaster::sdo_write(std::size_t axis, std::uint16_t index, std::uint8_t sub,
                                   std::uint32_t value, std::uint8_t size) {
  CanFrame q;
  q.id = kSdoRx + nodes_[axis].st.node;
  q.dlc = 8;
  q.data[0] = size == 1 ? kSdoDownload1 : size == 2 ? kSdoDownload2 : kSdoDownload4;
  put_u16(q.data + 1, index);
  q.data[3] = sub;
  put_u32(q.data + 4, value);
  CanFrame r;
  if (const AxisError e = sdo(axis, q, r); e != AxisError::none) return e;
  if (r.data[0] != kSdoDownloadAck) {
    ++counters_.stray_sdo;
    return fail(AxisError::timeout, axis, "an SDO download answered with the wrong command");
  }
  return AxisError::none;
}

AxisError CanOpenMaster::sdo_read(std::size_t axis, std::uint16_t index, std::uint8_t sub,
                                  std::uint32_t& value) {
  CanFrame q;
  q.id = kSdoRx + nodes_[axis].st.node;
  q.dlc = 8;
  q.data[0] = kSdoUpload;
  put_u16(q.data + 1, index);
  q.data[3] = sub;
  CanFrame r;
  if (const AxisError e = sdo(axis, q, r); e != AxisError::none) return e;
  const std::uint8_t cs = r.data[0];
  if (cs != kSdoUpload1 && cs != kSdoUpload2 && cs != kSdoUpload4 && cs != 0x47) {
    ++counters_.stray_sdo;
    return fail(AxisError::timeout, axis, "an SDO upload answered with the wrong command");
  }
  const int bytes = 4 - ((cs >> 2) & 3);  // expedited, size indicated: n = unused bytes
  value = 0;
  for (int i = 0; i < bytes; ++i) value |= std::uint32_t{r.data[4 + i]} << (8 * i);
  return AxisError::none;
}

AxisError CanOpenMaster::setup_node(std::size_t axis) {
  const std::uint32_t id = nodes_[axis].st.node;
  struct Write {
    std::uint16_t index;
    std::uint8_t sub;
    std::uint32_t value;
    std::uint8_t size;
  };
  const Write writes[] = {
      {kModeOfOperation, 0, static_cast<std::uint8_t>(kModeCsp), 1},
      {kInterpolationPeriod, 1, cfg_.sync_us / 1000, 1},
      {kInterpolationPeriod, 2, static_cast<std::uint8_t>(-3), 1},  // 10^-3 s: ms
      // RPDO1: controlword + target position, applied at each SYNC. A PDO
      // is switched off (COB-ID bit 31) while its mapping changes.
      {kRpdo1Comm, 1, kPdoInvalid | (kRpdo1 + id), 4},
      {kRpdo1Map, 0, 0, 1},
      {kRpdo1Map, 1, map_entry(kControlword, 0, 16), 4},
      {kRpdo1Map, 2, map_entry(kTargetPosition, 0, 32), 4},
      {kRpdo1Map, 0, 2, 1},
      {kRpdo1Comm, 2, kPdoSynchronous, 1},
      {kRpdo1Comm, 1, kRpdo1 + id, 4},
      // TPDO1: statusword + actual position, sent after each SYNC.
      {kTpdo1Comm, 1, kPdoInvalid | (kTpdo1 + id), 4},
      {kTpdo1Map, 0, 0, 1},
      {kTpdo1Map, 1, map_entry(kStatusword, 0, 16), 4},
      {kTpdo1Map, 2, map_entry(kActualPosition, 0, 32), 4},
      {kTpdo1Map, 0, 2, 1},
      {kTpdo1Comm, 2, kPdoSynchronous, 1},
      {kTpdo1Comm, 1, kTpdo1 + id, 4},
      {kHeartbeatTime, 0, cfg_.heartbeat_ms, 2},
  };
  for (const Write& w : writes)
    if (const AxisError e = sdo_write(axis, w.index, w.sub, w.value, w.size); e != AxisError::none)
      return e;
  std::uint32_t mode = 0;
  if (const AxisError e = sdo_read(axis, kModeDisplay, 0, mode); e != AxisError::none) return e;
  if (static_cast<std::int8_t>(mode) != kModeCsp)
    return fail(AxisError::sdo_abort, axis, "the drive does not display CSP mode (0x6061) after setup");
  // The first RPDO already carries the actual position: no target is ever
  // away from where the axis stands, enabled or not.
  std::uint32_t actual = 0;
  if (const AxisError e = sdo_read(axis, kActualPosition, 0, actual); e != AxisError::none) return e;
  nodes_[axis].st.actual = nodes_[axis].st.target = static_cast<std::int32_t>(actual);
  return AxisError::none;
}

AxisError CanOpenMaster::bring_up() {
  operational_ = enabled_ = faulted_ = false;
  for (Node& n : nodes_) {
    n.booted = false;
    n.nmt_state = 0xFF;
    n.emcy_new = false;
    n.st.emcy_code = 0;
  }
  for (const Node& n : nodes_)
    if (const AxisError e = nmt(kNmtResetNode, n.st.node); e != AxisError::none) return e;
  auto all_booted = [&] {
    for (const Node& n : nodes_)
      if (!n.booted) return false;
    return true;
  };
  if (const AxisError e = pump(bus_.now_us() + cfg_.boot_timeout_us, all_booted); e != AxisError::none)
    return e;
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    if (!nodes_[i].booted) return fail(AxisError::timeout, i, "no boot-up message after NMT reset node");
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    if (const AxisError e = setup_node(i); e != AxisError::none) return e;
  for (const Node& n : nodes_)
    if (const AxisError e = nmt(kNmtStart, n.st.node); e != AxisError::none) return e;
  const std::uint64_t now = bus_.now_us();
  for (Node& n : nodes_) n.last_heartbeat_us = now;  // the consumer starts counting now
  operational_ = true;
  next_sync_us_ = now;
  return AxisError::none;
}

AxisError CanOpenMaster::health() {
  const BusState bs = bus_.state();
  if (bs == BusState::passive && last_bus_ != BusState::passive) ++counters_.error_passive;
  last_bus_ = bs;
  if (bs == BusState::bus_off) return fail(AxisError::bus_off, SIZE_MAX, "the controller is bus-off");
  const std::uint64_t now = bus_.now_us();
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    Node& n = nodes_[i];
    if (n.emcy_new) {
      n.emcy_new = false;
      char what[64];
      std::snprintf(what, sizeof what, "EMCY error code 0x%04X", n.st.emcy_code);
      return fail(AxisError::emcy, i, what);
    }
    if (now - n.last_heartbeat_us > std::uint64_t{cfg_.heartbeat_timeout_ms} * 1000u) {
      char what[64];
      std::snprintf(what, sizeof what, "no heartbeat for %u ms", static_cast<unsigned>(cfg_.heartbeat_timeout_ms));
      return fail(AxisError::heartbeat_lost, i, what);
    }
    // Feedback from the previous SYNC is due by now; a drive that left
    // "operation enabled" has stopped following.
    if (enabled_ && n.st.feedback_cycle + 1 >= counters_.cycles &&
        decode_state(n.st.statusword) != DriveState::operation_enabled) {
      char what[64];
      std::snprintf(what, sizeof what, "statusword 0x%04X (%s)", n.st.statusword,
                    to_string(decode_state(n.st.statusword)));
      return fail(AxisError::drive_fault, i, what);
    }
  }
  return AxisError::none;
}

AxisError CanOpenMaster::cycle() {
  if (!operational_) return fail(AxisError::not_enabled, SIZE_MAX, "cycle before bring-up");
  // Feedback and heartbeats until this cycle's SYNC is due.
  AxisError err = pump(next_sync_us_, [] { return false; });
  if (err == AxisError::none) err = health();
  if (err == AxisError::bus_off) {
    // Nothing goes out, but time does: the next SYNC slot is a period on.
    next_sync_us_ += cfg_.sync_us;
    faulted_ = true;
    return err;
  }
  // The setpoints go out every cycle, fault or not: the drives still
  // running brake on the path with the rest.
  for (Node& n : nodes_) {
    CanFrame f;
    f.id = kRpdo1 + n.st.node;
    f.dlc = 6;
    put_u16(f.data, n.st.controlword);
    put_u32(f.data + 2, static_cast<std::uint32_t>(n.st.target));
    if (const AxisError e = send(f); e != AxisError::none && err == AxisError::none) err = e;
  }
  CanFrame sync;
  sync.id = kSync;
  if (const AxisError e = send(sync); e != AxisError::none && err == AxisError::none) err = e;
  ++counters_.cycles;
  next_sync_us_ += cfg_.sync_us;
  // More than a period late (the host stalled): start again from now rather
  // than send a burst of SYNCs to catch up.
  if (const std::uint64_t now = bus_.now_us(); now > next_sync_us_ + cfg_.sync_us) {
    ++counters_.late_syncs;
    next_sync_us_ = now;
  }
  if (err == AxisError::none) return err;
  if (faulted_) return AxisError::none;  // already reported; wait for fault_reset
  faulted_ = true;
  return err;
}

AxisError CanOpenMaster::transition(std::uint16_t controlword, int target_state, const char* step) {
  for (Node& n : nodes_) n.st.controlword = controlword;
  const auto want = static_cast<DriveState>(target_state);
  for (std::uint32_t k = 0; k < cfg_.enable_cycles; ++k) {
    const AxisError e = cycle();
    if (e != AxisError::none && e != AxisError::drive_fault) return e;
    bool all = true;
    for (const Node& n : nodes_)
      all = all && n.st.feedback_cycle + 1 == counters_.cycles && decode_state(n.st.statusword) == want;
    if (all) return AxisError::none;
  }
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    if (decode_state(nodes_[i].st.statusword) != want) {
      char what[120];
      std::snprintf(what, sizeof what, "%s: still '%s' (statusword 0x%04X) after %u SYNC cycles", step,
                    to_string(decode_state(nodes_[i].st.statusword)), nodes_[i].st.statusword,
                    static_cast<unsigned>(cfg_.enable_cycles));
      return fail(AxisError::enable_refused, i, what);
    }
  return fail(AxisError::enable_refused, SIZE_MAX, step);
}

AxisError CanOpenMaster::enable() {
  if (!operational_) return fail(AxisError::not_enabled, SIZE_MAX, "enable before bring-up");
  enabled_ = false;
  // One cycle with the controlword unchanged, for the actual positions: the
  // targets start there, so enabling never makes a drive jump.
  if (const AxisError e = cycle(); e != AxisError::none) return e;
  if (const AxisError e = cycle(); e != AxisError::none) return e;
  for (Node& n : nodes_) n.st.target = n.st.actual;
  if (const AxisError e = transition(kCwShutdown, static_cast<int>(DriveState::ready_to_switch_on), "shutdown");
      e != AxisError::none)
    return e;
  if (const AxisError e = transition(kCwSwitchOn, static_cast<int>(DriveState::switched_on), "switch on");
      e != AxisError::none)
    return e;
  for (Node& n : nodes_) n.st.target = n.st.actual;
  if (const AxisError e = transition(kCwEnableOperation, static_cast<int>(DriveState::operation_enabled),
                                     "enable operation");
      e != AxisError::none)
    return e;
  enabled_ = true;
  return AxisError::none;
}

AxisError CanOpenMaster::disable() {
  enabled_ = false;
  return transition(kCwShutdown, static_cast<int>(DriveState::ready_to_switch_on), "shutdown");
}

AxisError CanOpenMaster::fault_reset() {
  if (!bus_.recovered()) return fail(AxisError::bus_off, SIZE_MAX, "the bus has not recovered");
  enabled_ = false;
  faulted_ = false;
  const std::uint64_t now = bus_.now_us();
  for (Node& n : nodes_) {
    n.emcy_new = false;
    n.st.emcy_code = 0;
    n.last_heartbeat_us = now;
  }
  // Bit 7 low for a cycle, then high: the drive resets on the rising edge.
  for (Node& n : nodes_) n.st.controlword = kCwDisableVoltage;
  if (const AxisError e = cycle(); e != AxisError::none) return e;
  if (const AxisError e = transition(kCwFaultReset, static_cast<int>(DriveState::switch_on_disabled),
                                     "fault reset");
      e != AxisError::none)
    return e;
  return enable();
}

}  // namespace kerf::hal
