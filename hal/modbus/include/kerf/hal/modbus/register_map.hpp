// kerf's motion-board register map (see hal/modbus/REGISTERS.md). Shared by
// the host-side client and the simulated board so the two cannot drift.
// 32-bit values span two registers, high word first.
#pragma once

#include <cmath>
#include <cstdint>

#include "kerf/hal/segment_link.hpp"

namespace kerf::hal::modbus_map {

// 2: the actual position (16..19); 3: register 14 is a flag set (torch, thc_lock);
// 4: slot type 2 (z move) and pos_z (20..21), homing (22..23, command 7, block 40..51)
inline constexpr std::uint16_t kMapVersion = 4;
inline constexpr int kDefaultUnit = 17;

// Status block: holding registers 0..23, read-only.
inline constexpr int kStatusAddr = 0;
inline constexpr int kStatusRegs = 24;
// Command register, written with FC06.
inline constexpr int kCommandAddr = 32;
inline constexpr std::uint16_t kCommandHome = 7;  // home the axis of the home block
// Home block: written with FC16 before command 7.
inline constexpr int kHomeAddr = 40;
inline constexpr int kHomeRegs = 12;
// Segment slots: k consecutive slots written in one FC16/FC23 queue k segments.
inline constexpr int kSlotAddr = 64;
inline constexpr int kSlotRegs = 16;
inline constexpr int kMaxSlotsPerWrite = 7;  // 112 registers; FC23 allows 121
inline constexpr int kMapRegs = kSlotAddr + kSlotRegs * kMaxSlotsPerWrite;

// Offsets inside the status block.
enum StatusReg : int {
  kRegVersion = 0, kRegState = 1, kRegCredit = 2, kRegFaults = 3,
  kRegLastAccepted = 4, kRegExecuting = 6, kRegLastExecuted = 8,
  kRegPosX = 10, kRegPosY = 12, kRegTorch = 14, kRegDuplicates = 15,
  kRegActualX = 16, kRegActualY = 18, kRegPosZ = 20, kRegHomed = 22, kRegHoming = 23,
};
// Offsets inside the home block.
enum HomeReg : int {
  kHomeAxisMask = 0, kHomeDir = 1, kHomeSearchSpeed = 2, kHomeLatchSpeed = 4,
  kHomeSearchDistance = 6, kHomePosition = 8, kHomeBackoff = 10,
};
// Offsets inside a slot.
enum SlotReg : int {
  kSlotSeq = 0, kSlotKind = 2, kSlotDir = 3, kSlotEndX = 4, kSlotEndY = 6,
  kSlotCentreX = 8, kSlotCentreY = 10, kSlotFeed = 12, kSlotFlags = 14, kSlotReserved = 15,
};
inline constexpr std::uint16_t kFlagTorch = 1;
// Slot types (kSlotKind).
inline constexpr std::uint16_t kKindLine = 0, kKindArc = 1, kKindZMove = 2;
// Bits of status register 14 (kRegTorch).
inline constexpr std::uint16_t kStatusTorch = 1;
inline constexpr std::uint16_t kStatusThcLock = 2;  // speed below vad of the cut feed

// Lengths travel as micrometres, feed as micrometres per second.
inline constexpr double kUnitsPerMm = 1000.0;

inline void put32(std::uint16_t* r, std::uint32_t v) {
  r[0] = static_cast<std::uint16_t>(v >> 16);
  r[1] = static_cast<std::uint16_t>(v & 0xFFFFu);
}
inline std::uint32_t get32(const std::uint16_t* r) {
  return (static_cast<std::uint32_t>(r[0]) << 16) | r[1];
}
inline std::int32_t get_i32(const std::uint16_t* r) { return static_cast<std::int32_t>(get32(r)); }

// mm -> integer micrometres; false when it does not fit in 32 bits. The
// whole int32 range, -2^31 included: what decode_slot/decode_status accept
// must encode back (found by tests/fuzz/fuzz_modbus).
inline bool to_units(double mm, std::int32_t& out) {
  const double u = std::nearbyint(mm * kUnitsPerMm);
  if (!(u >= -2147483648.0 && u <= 2147483647.0)) return false;
  out = static_cast<std::int32_t>(u);
  return true;
}
inline double to_mm(std::int32_t units) { return units / kUnitsPerMm; }

// Fills one slot; false when a value is out of range.
bool encode_slot(const SegmentCommand& s, std::uint16_t* slot);
// Reads one slot; false (with a reason) when it is not a valid segment.
bool decode_slot(const std::uint16_t* slot, SegmentCommand& s, const char*& reason);

// The home block; false when a value is out of range (encode) or the block
// is not one axis, a direction of +-1 and positive speeds and lengths (decode).
bool encode_home(const HomeCommand& h, std::uint16_t* regs);
bool decode_home(const std::uint16_t* regs, HomeCommand& h, const char*& reason);

void encode_status(const BoardStatus& st, std::uint16_t* regs);
// false when the block is not this map's (version, state out of range).
bool decode_status(const std::uint16_t* regs, BoardStatus& st);

}  // namespace kerf::hal::modbus_map
