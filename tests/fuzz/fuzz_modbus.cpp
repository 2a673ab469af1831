// The Modbus register-block decoders (hal/modbus/register_map.hpp) on
// arbitrary registers: the status block the host reads from a board, and
// the segment slot a board reads from the host. Whatever decodes must keep
// the map's ranges and encode back to the very same registers.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fuzz_check.hpp"
#include "kerf/hal/modbus/register_map.hpp"

namespace map = kerf::hal::modbus_map;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Registers as the wire carries them: big-endian 16-bit words.
  std::uint16_t regs[map::kStatusRegs] = {};
  std::uint16_t slot[map::kSlotRegs] = {};
  for (std::size_t i = 0; i + 1 < size && i / 2 < map::kStatusRegs + map::kSlotRegs; i += 2) {
    const auto w = static_cast<std::uint16_t>((data[i] << 8) | data[i + 1]);
    if (i / 2 < map::kStatusRegs)
      regs[i / 2] = w;
    else
      slot[i / 2 - map::kStatusRegs] = w;
  }
  kerf::hal::BoardStatus st;
  if (map::decode_status(regs, st)) {
    FUZZ_CHECK(std::isfinite(st.position.x) && std::isfinite(st.position.y), "status position");
    std::uint16_t again[map::kStatusRegs] = {};
    map::encode_status(st, again);
    FUZZ_CHECK(std::memcmp(regs, again, sizeof regs) == 0, "status does not encode back");
  }
  kerf::hal::SegmentCommand seg;
  const char* reason = nullptr;
  if (map::decode_slot(slot, seg, reason)) {
    FUZZ_CHECK(seg.seq != 0 && seg.feed > 0, "slot seq/feed");
    FUZZ_CHECK(seg.kind == kerf::SegmentKind::arc ? (seg.dir == 1 || seg.dir == -1) : seg.dir == 0,
               "slot direction");
    std::uint16_t again[map::kSlotRegs] = {};
    FUZZ_CHECK(map::encode_slot(seg, again), "a decoded slot does not encode");
    FUZZ_CHECK(std::memcmp(slot, again, sizeof slot) == 0, "slot does not encode back");
  } else {
    FUZZ_CHECK(reason != nullptr && reason[0] != 0, "a refused slot without a reason");
  }
  return 0;
}
