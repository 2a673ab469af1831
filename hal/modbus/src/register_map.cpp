#include "kerf/hal/modbus/register_map.hpp"

namespace kerf::hal::modbus_map {

bool encode_slot(const SegmentCommand& s, std::uint16_t* slot) {
  std::int32_t ex = 0, ey = 0, cx = 0, cy = 0, feed = 0;
  if (!to_units(s.end.x, ex) || !to_units(s.end.y, ey)) return false;
  if (s.z_move) {  // centre_x carries the z end, centre_y and dir are 0
    if (s.kind != SegmentKind::line || s.dir != 0 || !to_units(s.z, cx)) return false;
  } else if (!to_units(s.centre.x, cx) || !to_units(s.centre.y, cy)) {
    return false;
  }
  if (!to_units(s.feed, feed) || feed <= 0) return false;
  put32(slot + kSlotSeq, s.seq);
  slot[kSlotKind] = s.z_move ? kKindZMove : s.kind == SegmentKind::arc ? kKindArc : kKindLine;
  slot[kSlotDir] = static_cast<std::uint16_t>(static_cast<std::int16_t>(s.dir));
  put32(slot + kSlotEndX, static_cast<std::uint32_t>(ex));
  put32(slot + kSlotEndY, static_cast<std::uint32_t>(ey));
  put32(slot + kSlotCentreX, static_cast<std::uint32_t>(cx));
  put32(slot + kSlotCentreY, static_cast<std::uint32_t>(cy));
  put32(slot + kSlotFeed, static_cast<std::uint32_t>(feed));
  slot[kSlotFlags] = s.torch ? kFlagTorch : 0;
  slot[kSlotReserved] = 0;
  return true;
}

bool decode_slot(const std::uint16_t* slot, SegmentCommand& s, const char*& reason) {
  s.seq = get32(slot + kSlotSeq);
  const std::uint16_t kind = slot[kSlotKind];
  const auto dir = static_cast<std::int16_t>(slot[kSlotDir]);
  const std::int32_t feed = get_i32(slot + kSlotFeed);
  if (s.seq == 0) { reason = "sequence number 0"; return false; }
  if (kind > kKindZMove) { reason = "unknown segment type"; return false; }
  if (kind == kKindArc && dir != 1 && dir != -1) { reason = "arc direction not +1/-1"; return false; }
  if (kind == kKindLine && dir != 0) { reason = "line with a direction"; return false; }
  if (kind == kKindZMove && (dir != 0 || get_i32(slot + kSlotCentreY) != 0)) {
    reason = "z move with a direction or centre_y";
    return false;
  }
  if (feed <= 0) { reason = "feed <= 0"; return false; }
  if ((slot[kSlotFlags] & ~kFlagTorch) != 0 || slot[kSlotReserved] != 0) {
    reason = "reserved bits set";
    return false;
  }
  s.kind = kind == kKindArc ? SegmentKind::arc : SegmentKind::line;
  s.dir = static_cast<std::int8_t>(dir);
  s.end = {to_mm(get_i32(slot + kSlotEndX)), to_mm(get_i32(slot + kSlotEndY))};
  s.z_move = kind == kKindZMove;
  s.z = s.z_move ? to_mm(get_i32(slot + kSlotCentreX)) : 0.0;
  s.centre = s.z_move ? Vec2<double>{} : Vec2<double>{to_mm(get_i32(slot + kSlotCentreX)), to_mm(get_i32(slot + kSlotCentreY))};
  s.feed = to_mm(feed);
  s.torch = (slot[kSlotFlags] & kFlagTorch) != 0;
  return true;
}

bool encode_home(const HomeCommand& h, std::uint16_t* r) {
  std::int32_t ss = 0, ls = 0, dist = 0, pos = 0, back = 0;
  if (h.axis < 0 || h.axis > 2 || h.dir < -1 || h.dir > 1) return false;
  if (!to_units(h.search_speed, ss) || !to_units(h.latch_speed, ls) || !to_units(h.search_distance, dist) ||
      !to_units(h.home_position, pos) || !to_units(h.backoff, back))
    return false;
  if (ss <= 0 || ls <= 0 || (dist <= 0 && h.dir != 0) || back < 0) return false;
  r[kHomeAxisMask] = static_cast<std::uint16_t>(1u << h.axis);
  r[kHomeDir] = static_cast<std::uint16_t>(static_cast<std::int16_t>(h.dir));
  put32(r + kHomeSearchSpeed, static_cast<std::uint32_t>(ss));
  put32(r + kHomeLatchSpeed, static_cast<std::uint32_t>(ls));
  put32(r + kHomeSearchDistance, static_cast<std::uint32_t>(dist));
  put32(r + kHomePosition, static_cast<std::uint32_t>(pos));
  put32(r + kHomeBackoff, static_cast<std::uint32_t>(back));
  return true;
}

bool decode_home(const std::uint16_t* r, HomeCommand& h, const char*& reason) {
  const std::uint16_t mask = r[kHomeAxisMask];
  if (mask != 1 && mask != 2 && mask != 4) { reason = "axis mask is not one of x, y, z"; return false; }
  const auto dir = static_cast<std::int16_t>(r[kHomeDir]);
  if (dir < -1 || dir > 1) { reason = "direction not -1, 0 or +1"; return false; }
  if (get_i32(r + kHomeSearchSpeed) <= 0 || get_i32(r + kHomeLatchSpeed) <= 0 ||
      (get_i32(r + kHomeSearchDistance) <= 0 && dir != 0) || get_i32(r + kHomeBackoff) < 0) {
    reason = "speed or distance <= 0";
    return false;
  }
  h.axis = mask == 1 ? 0 : mask == 2 ? 1 : 2;
  h.dir = dir;
  h.search_speed = to_mm(get_i32(r + kHomeSearchSpeed));
  h.latch_speed = to_mm(get_i32(r + kHomeLatchSpeed));
  h.search_distance = to_mm(get_i32(r + kHomeSearchDistance));
  h.home_position = to_mm(get_i32(r + kHomePosition));
  h.backoff = to_mm(get_i32(r + kHomeBackoff));
  return true;
}

void encode_status(const BoardStatus& st, std::uint16_t* r) {
  std::int32_t x = 0, y = 0;
  to_units(st.position.x, x);
  to_units(st.position.y, y);
  std::int32_t ax = 0, ay = 0, z = 0;
  to_units(st.actual.x, ax);
  to_units(st.actual.y, ay);
  to_units(st.z, z);
  r[kRegVersion] = kMapVersion;
  r[kRegState] = static_cast<std::uint16_t>(st.state);
  r[kRegCredit] = st.credit;
  r[kRegFaults] = st.faults;
  put32(r + kRegLastAccepted, st.last_accepted);
  put32(r + kRegExecuting, st.executing);
  put32(r + kRegLastExecuted, st.last_executed);
  put32(r + kRegPosX, static_cast<std::uint32_t>(x));
  put32(r + kRegPosY, static_cast<std::uint32_t>(y));
  r[kRegTorch] = static_cast<std::uint16_t>((st.torch ? kStatusTorch : 0) | (st.thc_lock ? kStatusThcLock : 0));
  r[kRegDuplicates] = st.duplicates;
  put32(r + kRegActualX, static_cast<std::uint32_t>(ax));
  put32(r + kRegActualY, static_cast<std::uint32_t>(ay));
  put32(r + kRegPosZ, static_cast<std::uint32_t>(z));
  r[kRegHomed] = st.homed;
  r[kRegHoming] = static_cast<std::uint16_t>(st.homing);
}

bool decode_status(const std::uint16_t* r, BoardStatus& st) {
  if (r[kRegVersion] != kMapVersion) return false;
  if (r[kRegState] > static_cast<std::uint16_t>(BoardState::fault)) return false;
  if ((r[kRegTorch] & ~(kStatusTorch | kStatusThcLock)) != 0) return false;
  if (r[kRegHomed] > 7 || r[kRegHoming] > static_cast<std::uint16_t>(HomingState::aborted)) return false;
  st.state = static_cast<BoardState>(r[kRegState]);
  st.credit = r[kRegCredit];
  st.faults = r[kRegFaults];
  st.last_accepted = get32(r + kRegLastAccepted);
  st.executing = get32(r + kRegExecuting);
  st.last_executed = get32(r + kRegLastExecuted);
  st.position = {to_mm(get_i32(r + kRegPosX)), to_mm(get_i32(r + kRegPosY))};
  st.torch = (r[kRegTorch] & kStatusTorch) != 0;
  st.thc_lock = (r[kRegTorch] & kStatusThcLock) != 0;
  st.duplicates = r[kRegDuplicates];
  st.actual = {to_mm(get_i32(r + kRegActualX)), to_mm(get_i32(r + kRegActualY))};
  st.z = to_mm(get_i32(r + kRegPosZ));
  st.homed = static_cast<std::uint8_t>(r[kRegHomed]);
  st.homing = static_cast<HomingState>(r[kRegHoming]);
  return true;
}

}  // namespace kerf::hal::modbus_map
