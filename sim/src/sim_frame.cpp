#include "sim_frame.hpp"

#include <modbus/modbus.h>

#include "kerf/hal/modbus/register_map.hpp"

namespace kerf::sim {

namespace map = hal::modbus_map;

int write_slots(MotionBoard& board, int addr, int nb, const std::uint8_t* data, int bytes) {
  if (addr != map::kSlotAddr || nb % map::kSlotRegs != 0 || nb / map::kSlotRegs < 1 ||
      nb / map::kSlotRegs > map::kMaxSlotsPerWrite)
    return MODBUS_EXCEPTION_ILLEGAL_DATA_ADDRESS;
  if (bytes < 2 * nb) return MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE;
  for (int k = 0; k < nb / map::kSlotRegs; ++k) {
    std::uint16_t slot[map::kSlotRegs];
    for (int i = 0; i < map::kSlotRegs; ++i) {
      const std::uint8_t* p = data + 2 * (k * map::kSlotRegs + i);
      slot[i] = static_cast<std::uint16_t>((p[0] << 8) | p[1]);
    }
    hal::SegmentCommand seg;
    const char* reason = nullptr;
    if (!map::decode_slot(slot, seg, reason)) return MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE;
    const Accept a = board.accept(seg);
    // Earlier slots of the write stay queued: a resend of the whole write is
    // still safe because the board drops the numbers it already has.
    if (a != Accept::queued && a != Accept::duplicate) return MODBUS_EXCEPTION_ILLEGAL_DATA_VALUE;
  }
  return 0;
}

std::uint16_t crc16(const std::uint8_t* p, int n) {
  std::uint16_t crc = 0xFFFF;
  for (int i = 0; i < n; ++i) {
    crc ^= p[i];
    for (int b = 0; b < 8; ++b) crc = (crc & 1) != 0 ? static_cast<std::uint16_t>((crc >> 1) ^ 0xA001) : static_cast<std::uint16_t>(crc >> 1);
  }
  return crc;
}

namespace {
void put_crc(std::uint8_t* r, int n) {  // over r[0..n-2), low byte first
  const std::uint16_t c = crc16(r, n - 2);
  r[n - 2] = static_cast<std::uint8_t>(c & 0xFF);
  r[n - 1] = static_cast<std::uint8_t>(c >> 8);
}
}  // namespace

int frame_wrong_unit(FrameKind kind, std::uint8_t* r, int n) {
  const int at = kind == FrameKind::tcp ? 6 : 0;
  if (n <= at) return n;
  r[at] = static_cast<std::uint8_t>(r[at] == 247 ? 1 : r[at] + 1);
  if (kind == FrameKind::rtu) put_crc(r, n);
  return n;
}

int frame_short(FrameKind kind, std::uint8_t* r, int n) {
  const int h = kind == FrameKind::tcp ? 7 : 1;
  const int tail = kind == FrameKind::tcp ? 0 : 2;
  const int fc = n > h ? r[h] : 0;
  if ((fc != MODBUS_FC_READ_HOLDING_REGISTERS && fc != MODBUS_FC_WRITE_AND_READ_REGISTERS) ||
      n < h + 2 + 2 + tail)
    return n;
  r[h + 1] = static_cast<std::uint8_t>(r[h + 1] - 2);  // byte count: one register fewer
  n -= 2;
  if (kind == FrameKind::tcp) {
    const int mbap_len = ((r[4] << 8) | r[5]) - 2;
    r[4] = static_cast<std::uint8_t>(mbap_len >> 8);
    r[5] = static_cast<std::uint8_t>(mbap_len & 0xFF);
  } else {
    put_crc(r, n);
  }
  return n;
}

int frame_bad_crc(std::uint8_t* r, int n) {
  if (n >= 2) r[n - 1] ^= 0xFF;
  return n;
}

}  // namespace kerf::sim
