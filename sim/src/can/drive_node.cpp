#include "kerf/sim/can/drive_node.hpp"

#include <cmath>

namespace kerf::sim {

using namespace hal::canopen;
using hal::CanFrame;

namespace {
constexpr std::uint16_t kEmcyOvercurrent = 0x2310;
constexpr std::uint16_t kEmcyFollowingError = 0x8611;
constexpr std::uint32_t kAbortCannotMap = 0x06040041;
constexpr std::uint32_t kAbortMapWhileValid = 0x06010000;  // unsupported access (PDO still valid)
constexpr std::uint32_t kDeviceTypeServo = 0x00020192;     // CiA 402, servo drive
}  // namespace

DriveNode::DriveNode(const DriveConfig& cfg, hal::CanBus& out) : cfg_(cfg), out_(out) {
  actual_ = cfg.start;
  actual_exact_ = cfg.start;
  target_ = command_ = cfg.start;
  reset_node(0, false);
}

void DriveNode::reset_node(std::uint64_t now_us, bool announce) {
  const std::uint32_t node = cfg_.node;
  // Power-on values: PDOs off with the predefined COB-IDs, heartbeat off.
  const Entry defaults[] = {
      {0x1000, 0, 4, false, kDeviceTypeServo},
      {kHeartbeatTime, 0, 2, true, 0},
      {kRpdo1Comm, 1, 4, true, kPdoInvalid | (kRpdo1 + node)},
      {kRpdo1Comm, 2, 1, true, 0xFF},
      {kRpdo1Map, 0, 1, true, 0},
      {kRpdo1Map, 1, 4, true, 0},
      {kRpdo1Map, 2, 4, true, 0},
      {kTpdo1Comm, 1, 4, true, kPdoInvalid | (kTpdo1 + node)},
      {kTpdo1Comm, 2, 1, true, 0xFF},
      {kTpdo1Map, 0, 1, true, 0},
      {kTpdo1Map, 1, 4, true, 0},
      {kTpdo1Map, 2, 4, true, 0},
      {kControlword, 0, 2, true, 0},
      {kStatusword, 0, 2, false, 0},
      {kModeOfOperation, 0, 1, true, 0},
      {kModeDisplay, 0, 1, false, 0},
      {kActualPosition, 0, 4, false, 0},
      {kFollowingWindow, 0, 4, true, cfg_.following_window},
      {kTargetPosition, 0, 4, true, 0},
      {kInterpolationPeriod, 1, 1, true, 1},
      {kInterpolationPeriod, 2, 1, true, static_cast<std::uint8_t>(-3)},
      {kHomingMethod, 0, 1, true, static_cast<std::uint8_t>(kHomeNegativeSwitch)},
      {kHomingSpeeds, 1, 4, true, 10000},
      {kHomingSpeeds, 2, 4, true, 1000},
      {kHomeOffset, 0, 4, true, 0},
  };
  od_count_ = 0;
  for (const Entry& e : defaults) od_[od_count_++] = e;
  state_ = DriveState::switch_on_disabled;
  last_cw_ = 0;
  pending_ = false;
  following_error_ = false;
  target_ = command_ = actual_;
  homing_ = Homing::idle;
  nmt_ = kHbBootUp;
  if (announce) {
    CanFrame boot;
    boot.id = kHeartbeat + cfg_.node;
    boot.dlc = 1;
    boot.data[0] = kHbBootUp;
    send(boot);
  }
  nmt_ = kHbPreOperational;
  next_heartbeat_us_ = now_us;
}

void DriveNode::power_on(std::uint64_t now_us) {
  referenced_ = false;
  reset_node(now_us, true);
}

DriveNode::Entry* DriveNode::find(std::uint16_t index, std::uint8_t sub) {
  for (int i = 0; i < od_count_; ++i)
    if (od_[i].index == index && od_[i].sub == sub) return &od_[i];
  return nullptr;
}

std::uint32_t DriveNode::od(std::uint16_t index, std::uint8_t sub) const {
  for (int i = 0; i < od_count_; ++i)
    if (od_[i].index == index && od_[i].sub == sub) return od_[i].value;
  return 0;
}

std::uint16_t DriveNode::statusword() const {
  std::uint16_t sw = encode_state(state_);
  if (following_error_) sw |= kSwFollowingError;
  if (static_cast<std::int8_t>(od(kModeDisplay, 0)) == kModeHoming) {
    sw = static_cast<std::uint16_t>(sw & ~kSwFollowingError);
    if (homing_ == Homing::attained || (homing_ == Homing::idle && referenced_)) sw |= kSwHomingAttained;
    if (homing_ != Homing::search && homing_ != Homing::release) sw |= kSwTargetReached;
    return sw;
  }
  if (state_ == DriveState::operation_enabled) sw |= 1u << 12;  // CSP: the drive follows the target
  return sw;
}

void DriveNode::send(const CanFrame& f) {
  if (injected_ == DriveFault::heartbeat_loss) return;  // silent
  if (out_.send(f) != hal::CanResult::ok) ++counters_.send_refused;
}

void DriveNode::handle(const CanFrame& f, std::uint64_t now_us) {
  if (injected_ == DriveFault::heartbeat_loss) return;
  if (f.id == kNmt) return on_nmt(f, now_us);
  if (f.id == kSync) {
    if (f.dlc != 0 && f.dlc != 1) {
      ++counters_.bad_dlc;
      return;
    }
    return on_sync();
  }
  if (f.id == kSdoRx + cfg_.node) return on_sdo(f);
  const std::uint32_t rpdo = od(kRpdo1Comm, 1);
  if ((rpdo & kPdoInvalid) == 0 && f.id == (rpdo & 0x7FF)) return on_rpdo(f);
  // Anything else is another node's business.
}

void DriveNode::on_nmt(const CanFrame& f, std::uint64_t now_us) {
  if (f.dlc != 2) {
    ++counters_.bad_dlc;
    return;
  }
  if (f.data[1] != 0 && f.data[1] != cfg_.node) return;
  switch (f.data[0]) {
    case kNmtStart: nmt_ = kHbOperational; break;
    case kNmtStop: nmt_ = kHbStopped; break;
    case kNmtPreOperational: nmt_ = kHbPreOperational; break;
    case kNmtResetNode:
    case kNmtResetComm: reset_node(now_us, true); break;
    default: break;
  }
}

void DriveNode::sdo_abort(const CanFrame& req, std::uint32_t code) {
  CanFrame r;
  r.id = kSdoTx + cfg_.node;
  r.dlc = 8;
  r.data[0] = kSdoAbort;
  r.data[1] = req.data[1];
  r.data[2] = req.data[2];
  r.data[3] = req.data[3];
  put_u32(r.data + 4, code);
  ++counters_.sdo_aborts;
  send(r);
}

std::uint32_t DriveNode::check_write(const Entry& e, std::uint32_t value) const {
  if (e.index == kModeOfOperation && static_cast<std::int8_t>(value) != kModeCsp &&
      static_cast<std::int8_t>(value) != kModeHoming)
    return kAbortRange;
  if (e.index == kHomingMethod && static_cast<std::int8_t>(value) != kHomeNegativeSwitch &&
      static_cast<std::int8_t>(value) != kHomePositiveSwitch)
    return kAbortRange;
  if (e.index == kInterpolationPeriod && e.sub == 1 && (value < 1 || value > 10)) return kAbortRange;
  if (e.index == kInterpolationPeriod && e.sub == 2 && static_cast<std::int8_t>(value) != -3) return kAbortRange;
  const bool rpdo_map = e.index == kRpdo1Map, tpdo_map = e.index == kTpdo1Map;
  if (rpdo_map || tpdo_map) {
    // The mapping may change only while the PDO is switched off.
    if ((od(rpdo_map ? kRpdo1Comm : kTpdo1Comm, 1) & kPdoInvalid) == 0) return kAbortMapWhileValid;
    if (e.sub == 0) return value <= 2 ? 0 : kAbortRange;
    const auto index = static_cast<std::uint16_t>(value >> 16);
    const auto bits = value & 0xFF;
    const bool ok = rpdo_map ? ((index == kControlword && bits == 16) || (index == kTargetPosition && bits == 32))
                             : ((index == kStatusword && bits == 16) || (index == kActualPosition && bits == 32));
    if (!ok || ((value >> 8) & 0xFF) != 0) return kAbortCannotMap;
  }
  return 0;
}

void DriveNode::on_sdo(const CanFrame& f) {
  if (f.dlc != 8) {  // CiA 301: SDO frames are always 8 bytes
    ++counters_.bad_dlc;
    return;
  }
  const std::uint8_t cs = f.data[0];
  const std::uint16_t index = get_u16(f.data + 1);
  const std::uint8_t sub = f.data[3];
  Entry* e = find(index, sub);
  const bool download = (cs & 0xE0) == 0x20;
  const bool upload = cs == kSdoUpload;
  if (!download && !upload) return sdo_abort(f, kAbortBadCommand);
  if (e == nullptr) {
    bool index_known = false;
    for (int i = 0; i < od_count_; ++i) index_known = index_known || od_[i].index == index;
    return sdo_abort(f, index_known ? kAbortNoSubindex : kAbortNoObject);
  }
  CanFrame r;
  r.id = kSdoTx + cfg_.node;
  r.dlc = 8;
  r.data[1] = f.data[1];
  r.data[2] = f.data[2];
  r.data[3] = sub;
  if (upload) {
    std::uint32_t v = e->value;
    if (index == kStatusword) v = statusword();
    if (index == kActualPosition) v = static_cast<std::uint32_t>(actual_);
    r.data[0] = static_cast<std::uint8_t>(0x43 | ((4 - e->size) << 2));
    put_u32(r.data + 4, v);
    return send(r);
  }
  // Only expedited transfers with the size indicated (e = s = 1).
  if ((cs & 0x03) != 0x03) return sdo_abort(f, kAbortBadCommand);
  const int size = 4 - ((cs >> 2) & 3);
  if (!e->writable) return sdo_abort(f, kAbortReadOnly);
  if (size != e->size) return sdo_abort(f, kAbortLength);
  std::uint32_t value = 0;
  for (int i = 0; i < size; ++i) value |= std::uint32_t{f.data[4 + i]} << (8 * i);
  if (const std::uint32_t code = check_write(*e, value); code != 0) return sdo_abort(f, code);
  e->value = value;
  if (index == kModeOfOperation) {
    if (Entry* shown = find(kModeDisplay, 0); shown != nullptr) shown->value = value;
    homing_ = Homing::idle;
    target_ = command_ = actual_;  // a change of mode never jumps
  }
  if (index == kControlword) apply_controlword(static_cast<std::uint16_t>(value));
  if (index == kTargetPosition) target_ = static_cast<std::int32_t>(value);
  r.data[0] = kSdoDownloadAck;
  send(r);
}

void DriveNode::on_rpdo(const CanFrame& f) {
  if (nmt_ != kHbOperational) return;
  // The mapped length decides the DLC; anything else is refused.
  const std::uint32_t n = od(kRpdo1Map, 0);
  std::uint32_t bytes = 0;
  for (std::uint8_t s = 1; s <= n; ++s) bytes += (od(kRpdo1Map, s) & 0xFF) / 8;
  if (f.dlc != bytes || bytes == 0) {
    ++counters_.bad_dlc;
    return;
  }
  ++counters_.rpdos;
  std::uint32_t at = 0;
  for (std::uint8_t s = 1; s <= n; ++s) {
    const std::uint32_t m = od(kRpdo1Map, s);
    if ((m >> 16) == kControlword) pending_cw_ = get_u16(f.data + at);
    else pending_target_ = static_cast<std::int32_t>(get_u32(f.data + at));
    at += (m & 0xFF) / 8;
  }
  pending_ = true;  // synchronous: applied at the next SYNC
}

void DriveNode::apply_controlword(std::uint16_t cw) {
  const bool reset_edge = (cw & kCwFaultReset) && !(last_cw_ & kCwFaultReset);
  const bool start_edge = (cw & kCwHomingStart) && !(last_cw_ & kCwHomingStart);
  last_cw_ = cw;
  if (static_cast<std::int8_t>(od(kModeDisplay, 0)) == kModeHoming && state_ == DriveState::operation_enabled) {
    if ((cw & kCwHalt) != 0 && (homing_ == Homing::search || homing_ == Homing::release)) homing_ = Homing::halted;
    else if (start_edge && (cw & kCwHalt) == 0) {
      homing_ = Homing::search;
      referenced_ = false;
    }
  }
  if (state_ == DriveState::fault) {
    if (reset_edge) {
      state_ = DriveState::switch_on_disabled;
      following_error_ = false;
      if (injected_ == DriveFault::emcy) injected_ = DriveFault::none;
      send_emcy(0);  // error reset
    }
    return;
  }
  if (cw & kCwFaultReset) return;  // bit 7 set: no other command acts
  const bool disable_voltage = (cw & 0x02) == 0;
  const bool quick_stop = (cw & 0x06) == 0x02;
  const bool shutdown = (cw & 0x07) == 0x06;
  const bool switch_on = (cw & 0x0F) == 0x07;
  const bool enable_op = (cw & 0x0F) == 0x0F;
  if (disable_voltage) {
    state_ = DriveState::switch_on_disabled;
    return;
  }
  switch (state_) {
    case DriveState::switch_on_disabled:
      if (shutdown) state_ = DriveState::ready_to_switch_on;
      break;
    case DriveState::ready_to_switch_on:
      if (quick_stop) state_ = DriveState::switch_on_disabled;
      else if (switch_on || enable_op) state_ = DriveState::switched_on;
      break;
    case DriveState::switched_on:
      if (quick_stop) state_ = DriveState::switch_on_disabled;
      else if (shutdown) state_ = DriveState::ready_to_switch_on;
      else if (enable_op && injected_ != DriveFault::enable_refused) {
        state_ = DriveState::operation_enabled;
        target_ = command_ = actual_;  // enabling never jumps
      }
      break;
    case DriveState::operation_enabled:
      if (quick_stop) state_ = DriveState::quick_stop_active;
      else if (shutdown) state_ = DriveState::ready_to_switch_on;
      else if (switch_on) state_ = DriveState::switched_on;
      break;
    case DriveState::quick_stop_active:
      break;  // only "disable voltage" leaves it (above)
    default: break;
  }
}

void DriveNode::send_emcy(std::uint16_t code) {
  CanFrame e;
  e.id = kEmcy + cfg_.node;
  e.dlc = 8;
  put_u16(e.data, code);
  e.data[2] = code == 0 ? 0 : 0x01;  // error register: generic error
  send(e);
}

void DriveNode::enter_fault(std::uint16_t code) {
  state_ = DriveState::fault;
  send_emcy(code);
}

void DriveNode::on_sync() {
  ++counters_.syncs;
  if (nmt_ != kHbOperational) return;
  if (pending_) {
    pending_ = false;
    apply_controlword(pending_cw_);
    if (state_ == DriveState::operation_enabled) target_ = pending_target_;
  }
  if (static_cast<std::int8_t>(od(kModeDisplay, 0)) == kModeHoming) {
    if (state_ == DriveState::operation_enabled) homing_step();
    target_ = command_ = actual_;
    if ((od(kTpdo1Comm, 1) & kPdoInvalid) == 0) send_tpdo();
    return;
  }
  // The plant: closes `lag_alpha` of the gap to the previous SYNC's command.
  if (injected_ != DriveFault::stall)
    actual_exact_ += cfg_.lag_alpha * (static_cast<double>(command_) - actual_exact_);
  actual_ = static_cast<std::int32_t>(std::lround(actual_exact_));
  if (state_ == DriveState::operation_enabled) {
    command_ = target_;
    const std::int64_t err = std::int64_t{target_} - actual_;
    const std::uint32_t window = od(kFollowingWindow, 0);
    if (static_cast<std::uint64_t>(err < 0 ? -err : err) > window) {
      following_error_ = true;
      enter_fault(kEmcyFollowingError);
    }
  } else {
    command_ = actual_;  // not enabled: the axis stays where it is
    target_ = actual_;
  }
  if ((od(kTpdo1Comm, 1) & kPdoInvalid) == 0) send_tpdo();
}

bool DriveNode::switch_tripped() const {
  if (!cfg_.has_home_switch) return false;
  return static_cast<std::int8_t>(od(kHomingMethod, 0)) == kHomeNegativeSwitch ? actual_ <= cfg_.home_switch
                                                                                 : actual_ >= cfg_.home_switch;
}

// Method 17/18: towards the switch at the search speed; once on it, off it at
// the zero speed; where it releases is the home position (0x607C). The drive
// searches without end: the master stops it (halt) past its search distance.
void DriveNode::homing_step() {
  if (homing_ != Homing::search && homing_ != Homing::release) return;
  const double dt = od(kInterpolationPeriod, 1) * 1e-3;  // ms (index -3)
  const double dir = static_cast<std::int8_t>(od(kHomingMethod, 0)) == kHomeNegativeSwitch ? -1.0 : 1.0;
  if (homing_ == Homing::search) {
    actual_exact_ += dir * od(kHomingSpeeds, 1) * dt;
    actual_ = static_cast<std::int32_t>(std::lround(actual_exact_));
    if (switch_tripped()) homing_ = Homing::release;
    return;
  }
  actual_exact_ -= dir * od(kHomingSpeeds, 2) * dt;
  actual_ = static_cast<std::int32_t>(std::lround(actual_exact_));
  if (!switch_tripped()) {
    latched_ = actual_;
    actual_ = static_cast<std::int32_t>(od(kHomeOffset, 0));
    actual_exact_ = actual_;
    homing_ = Homing::attained;
    referenced_ = true;
  }
}

void DriveNode::send_tpdo() {
  CanFrame t;
  t.id = od(kTpdo1Comm, 1) & 0x7FF;
  const std::uint32_t n = od(kTpdo1Map, 0);
  std::uint32_t at = 0;
  for (std::uint8_t s = 1; s <= n; ++s) {
    const std::uint32_t m = od(kTpdo1Map, s);
    if ((m >> 16) == kStatusword) put_u16(t.data + at, statusword());
    else put_u32(t.data + at, static_cast<std::uint32_t>(actual_));
    at += (m & 0xFF) / 8;
  }
  t.dlc = static_cast<std::uint8_t>(at);
  send(t);
}

void DriveNode::tick(std::uint64_t now_us) {
  const std::uint32_t period_ms = od(kHeartbeatTime, 0);
  if (period_ms == 0 || now_us < next_heartbeat_us_) return;
  CanFrame hb;
  hb.id = kHeartbeat + cfg_.node;
  hb.dlc = 1;
  hb.data[0] = nmt_;
  send(hb);
  next_heartbeat_us_ = now_us + std::uint64_t{period_ms} * 1000u;
}

std::uint64_t DriveNode::next_event_us() const {
  return od(kHeartbeatTime, 0) == 0 ? UINT64_MAX : next_heartbeat_us_;
}

void DriveNode::inject(DriveFault f, std::uint64_t) {
  injected_ = f;
  if (f == DriveFault::emcy) enter_fault(kEmcyOvercurrent);
}

}  // namespace kerf::sim
