// CANopen (CiA 301) and CiA 402 constants and frame helpers shared by the
// master (hal/can) and the simulated drive (sim/can). Predefined connection
// set: the COB-ID is a function code plus the node id.
#pragma once

#include <cstdint>

#include "kerf/hal/can_bus.hpp"

namespace kerf::hal::canopen {

// Function codes (CiA 301 predefined connection set).
inline constexpr std::uint32_t kNmt = 0x000;
inline constexpr std::uint32_t kSync = 0x080;
inline constexpr std::uint32_t kEmcy = 0x080;       // + node
inline constexpr std::uint32_t kTpdo1 = 0x180;      // + node
inline constexpr std::uint32_t kRpdo1 = 0x200;      // + node
inline constexpr std::uint32_t kSdoTx = 0x580;      // + node, server -> client
inline constexpr std::uint32_t kSdoRx = 0x600;      // + node, client -> server
inline constexpr std::uint32_t kHeartbeat = 0x700;  // + node

// NMT commands (byte 0 of the NMT frame; byte 1 is the node, 0 = all).
inline constexpr std::uint8_t kNmtStart = 0x01;
inline constexpr std::uint8_t kNmtStop = 0x02;
inline constexpr std::uint8_t kNmtPreOperational = 0x80;
inline constexpr std::uint8_t kNmtResetNode = 0x81;
inline constexpr std::uint8_t kNmtResetComm = 0x82;

// Heartbeat states.
inline constexpr std::uint8_t kHbBootUp = 0x00;
inline constexpr std::uint8_t kHbStopped = 0x04;
inline constexpr std::uint8_t kHbOperational = 0x05;
inline constexpr std::uint8_t kHbPreOperational = 0x7F;

// Expedited SDO command specifiers: download (write) by size, upload (read).
inline constexpr std::uint8_t kSdoDownload1 = 0x2F;
inline constexpr std::uint8_t kSdoDownload2 = 0x2B;
inline constexpr std::uint8_t kSdoDownload4 = 0x23;
inline constexpr std::uint8_t kSdoUpload = 0x40;
inline constexpr std::uint8_t kSdoDownloadAck = 0x60;
inline constexpr std::uint8_t kSdoUpload1 = 0x4F;
inline constexpr std::uint8_t kSdoUpload2 = 0x4B;
inline constexpr std::uint8_t kSdoUpload4 = 0x43;
inline constexpr std::uint8_t kSdoAbort = 0x80;

// SDO abort codes used here.
inline constexpr std::uint32_t kAbortBadCommand = 0x05040001;
inline constexpr std::uint32_t kAbortReadOnly = 0x06010002;
inline constexpr std::uint32_t kAbortNoObject = 0x06020000;
inline constexpr std::uint32_t kAbortLength = 0x06070010;
inline constexpr std::uint32_t kAbortNoSubindex = 0x06090011;
inline constexpr std::uint32_t kAbortRange = 0x06090030;
inline constexpr std::uint32_t kAbortState = 0x08000022;  // not in this device state

// Object dictionary entries used.
inline constexpr std::uint16_t kHeartbeatTime = 0x1017;  // u16 ms
inline constexpr std::uint16_t kRpdo1Comm = 0x1400;      // 1: COB-ID, 2: type
inline constexpr std::uint16_t kRpdo1Map = 0x1600;
inline constexpr std::uint16_t kTpdo1Comm = 0x1800;
inline constexpr std::uint16_t kTpdo1Map = 0x1A00;
inline constexpr std::uint16_t kControlword = 0x6040;
inline constexpr std::uint16_t kStatusword = 0x6041;
inline constexpr std::uint16_t kModeOfOperation = 0x6060;  // i8, 8 = CSP
inline constexpr std::uint16_t kModeDisplay = 0x6061;
inline constexpr std::uint16_t kActualPosition = 0x6064;   // i32
inline constexpr std::uint16_t kFollowingWindow = 0x6065;  // u32 counts
inline constexpr std::uint16_t kTargetPosition = 0x607A;   // i32
inline constexpr std::uint16_t kInterpolationPeriod = 0x60C2;  // 1: value, 2: index (10^x s)
inline constexpr std::int8_t kModeCsp = 8;
// Homing mode (CiA 402 mode 6): the drive runs the search itself.
inline constexpr std::int8_t kModeHoming = 6;
inline constexpr std::uint16_t kHomeOffset = 0x607C;    // i32 counts: the home position
inline constexpr std::uint16_t kHomingMethod = 0x6098;  // i8
inline constexpr std::uint16_t kHomingSpeeds = 0x6099;  // 1: search (to the switch), 2: zero (latch), counts/s
// Methods 17 and 18: the negative / positive switch, home at its falling edge
// (moving off it slowly), no index pulse.
inline constexpr std::int8_t kHomeNegativeSwitch = 17, kHomePositiveSwitch = 18;
inline constexpr std::uint32_t kPdoInvalid = 0x80000000u;  // COB-ID bit 31: PDO off
inline constexpr std::uint8_t kPdoSynchronous = 1;         // transmission type: every SYNC

// A PDO mapping entry: index, subindex, length in bits.
constexpr std::uint32_t map_entry(std::uint16_t index, std::uint8_t sub, std::uint8_t bits) {
  return (std::uint32_t{index} << 16) | (std::uint32_t{sub} << 8) | bits;
}

// Controlword commands (CiA 402 device control).
inline constexpr std::uint16_t kCwDisableVoltage = 0x0000;
inline constexpr std::uint16_t kCwShutdown = 0x0006;
inline constexpr std::uint16_t kCwSwitchOn = 0x0007;
inline constexpr std::uint16_t kCwEnableOperation = 0x000F;
inline constexpr std::uint16_t kCwQuickStop = 0x0002;
inline constexpr std::uint16_t kCwFaultReset = 0x0080;  // acts on the rising edge

// Drive states as decoded from the statusword (CiA 402).
enum class DriveState : std::uint8_t {
  not_ready,
  switch_on_disabled,
  ready_to_switch_on,
  switched_on,
  operation_enabled,
  quick_stop_active,
  fault_reaction_active,
  fault,
};

// Bits 0-3, 5 and 6 decide the state; the masks are the standard's table.
constexpr DriveState decode_state(std::uint16_t sw) {
  if ((sw & 0x4F) == 0x00) return DriveState::not_ready;
  if ((sw & 0x4F) == 0x40) return DriveState::switch_on_disabled;
  if ((sw & 0x6F) == 0x21) return DriveState::ready_to_switch_on;
  if ((sw & 0x6F) == 0x23) return DriveState::switched_on;
  if ((sw & 0x6F) == 0x27) return DriveState::operation_enabled;
  if ((sw & 0x6F) == 0x07) return DriveState::quick_stop_active;
  if ((sw & 0x4F) == 0x0F) return DriveState::fault_reaction_active;
  if ((sw & 0x4F) == 0x08) return DriveState::fault;
  return DriveState::not_ready;
}

// Statusword of a state (bit 4 voltage enabled and bit 9 remote set as a
// powered drive under network control reports them).
constexpr std::uint16_t encode_state(DriveState s) {
  switch (s) {
    case DriveState::not_ready: return 0x0200;
    case DriveState::switch_on_disabled: return 0x0250;
    case DriveState::ready_to_switch_on: return 0x0231;
    case DriveState::switched_on: return 0x0233;
    case DriveState::operation_enabled: return 0x0237;
    case DriveState::quick_stop_active: return 0x0217;
    case DriveState::fault_reaction_active: return 0x021F;
    case DriveState::fault: return 0x0218;
  }
  return 0;
}

inline constexpr std::uint16_t kSwFollowingError = 1u << 13;  // CSP
// Homing mode: controlword bit 4 starts it (rising edge), bit 8 halts it;
// statusword bit 10 target reached (ended or halted), 12 homing attained, 13 homing error.
inline constexpr std::uint16_t kCwHomingStart = 1u << 4;
inline constexpr std::uint16_t kCwHalt = 1u << 8;
inline constexpr std::uint16_t kSwTargetReached = 1u << 10;
inline constexpr std::uint16_t kSwHomingAttained = 1u << 12;
inline constexpr std::uint16_t kSwHomingError = 1u << 13;

const char* to_string(DriveState s);

// Little-endian field access, as CANopen puts every value on the wire.
inline void put_u16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
inline void put_u32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
inline std::uint16_t get_u16(const std::uint8_t* p) {
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}
inline std::uint32_t get_u32(const std::uint8_t* p) {
  return std::uint32_t{p[0]} | (std::uint32_t{p[1]} << 8) | (std::uint32_t{p[2]} << 16) |
         (std::uint32_t{p[3]} << 24);
}

// Bits on the wire for one standard data frame with worst-case bit
// stuffing: 47 bits of overhead (SOF to interframe space) plus the data,
// and one stuff bit per 4 bits over the 34 + 8*DLC stuffed bits.
constexpr std::uint32_t worst_case_bits(std::uint8_t dlc) {
  return 47u + 8u * dlc + (34u + 8u * dlc - 1u) / 4u;
}

}  // namespace kerf::hal::canopen
