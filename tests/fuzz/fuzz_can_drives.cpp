// The CANopen master and the simulated CiA 402 drives (sim/can) on the
// in-process bus, brought up and enabled for real, then fed fuzzed frames
// both ways between fuzzed master calls: frames from a foreign node to the
// master (TPDO, heartbeat, EMCY, SDO replies, anything) and frames from the
// master's port to the drives (the drives' SDO server and RPDO decoding).
// Nothing may crash or hang, every error has a reason, and a TPDO of the
// wrong length is refused.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "fuzz_check.hpp"
#include "kerf/hal/can/canopen_master.hpp"
#include "kerf/hal/canopen.hpp"
#include "kerf/sim/can/virtual_can_bus.hpp"

namespace {

using namespace kerf::hal;
using namespace kerf::hal::canopen;

CanFrame fuzzed_frame(FuzzedDataProvider& in) {
  static constexpr std::uint32_t kFunctions[] = {kNmt, kSync, kTpdo1, kRpdo1, kSdoTx, kSdoRx, kHeartbeat};
  CanFrame f;
  const std::uint8_t pick = in.ConsumeIntegral<std::uint8_t>();
  if (pick < 7 * 32) {  // a CANopen function of node 0..3 (1 and 2 exist)
    f.id = kFunctions[pick / 32] + (pick % 4);
  } else {
    f.id = in.ConsumeIntegral<std::uint16_t>() & 0x7FF;
  }
  f.dlc = in.ConsumeIntegralInRange<std::uint8_t>(0, 8);
  for (int i = 0; i < 8; ++i) f.data[i] = in.ConsumeIntegral<std::uint8_t>();
  return f;
}

void expect_reason(AxisError e, const CanOpenMaster& m) {
  if (e != AxisError::none) FUZZ_CHECK(m.last_error()[0] != 0, "an error without a reason");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  kerf::sim::VirtualCanBus bus;
  CanOpenConfig cfg;
  cfg.nodes = {1, 2};
  cfg.enable_cycles = 20;
  for (std::uint8_t node : cfg.nodes) {
    kerf::sim::DriveConfig d;
    d.node = node;
    d.start = 1000 * node;
    bus.add_drive(d);
  }
  std::string error;
  auto master = CanOpenMaster::create(bus.master(), cfg, error);
  FUZZ_CHECK(master != nullptr, error.c_str());
  FUZZ_CHECK(master->bring_up() == AxisError::none, master->last_error());
  FUZZ_CHECK(master->enable() == AxisError::none, master->last_error());
  for (int step = 0; step < 48 && in.remaining_bytes() > 0; ++step) {
    AxisError e = AxisError::none;
    const std::size_t axis = in.ConsumeIntegral<std::uint8_t>() % 2;
    switch (in.ConsumeIntegral<std::uint8_t>() % 9) {
      case 0:
      case 1: {
        const CanFrame f = fuzzed_frame(in);
        const std::uint64_t bad_before = master->counters().bad_dlc;
        bus.inject_frame(f);
        e = master->cycle();
        // A TPDO of a configured node with the wrong length is counted and dropped.
        const bool bad_tpdo = (f.id == kTpdo1 + 1 || f.id == kTpdo1 + 2) && f.dlc != 6;
        if (bad_tpdo && e != AxisError::bus_off)
          FUZZ_CHECK(master->counters().bad_dlc > bad_before, "a TPDO of the wrong length was not refused");
        break;
      }
      case 2:  // to the drives, as if the master had sent it
        bus.master().send(fuzzed_frame(in));
        e = master->cycle();
        break;
      case 3: {  // a fuzzed TPDO may have put the actual position at the edge of int32
        const std::int64_t near = std::int64_t{master->axis(axis).actual} + in.ConsumeIntegralInRange<int>(-50, 50);
        master->set_target(axis, static_cast<std::int32_t>(std::clamp<std::int64_t>(near, INT32_MIN, INT32_MAX)));
        e = master->cycle();
        break;
      }
      case 4: e = master->enable(); break;
      case 5: e = master->fault_reset(); break;
      case 6: {
        std::uint32_t v = 0;
        e = master->sdo_read(axis, in.ConsumeIntegral<std::uint16_t>(), in.ConsumeIntegral<std::uint8_t>(), v);
        break;
      }
      case 7: {
        const std::uint8_t sizes[] = {1, 2, 4};
        e = master->sdo_write(axis, in.ConsumeIntegral<std::uint16_t>(), in.ConsumeIntegral<std::uint8_t>(),
                              in.ConsumeIntegral<std::uint32_t>(), sizes[in.ConsumeIntegral<std::uint8_t>() % 3]);
        break;
      }
      default:
        if (in.ConsumeBool()) bus.inject_bus_off(); else bus.recover();
        e = master->cycle();
    }
    expect_reason(e, *master);
  }
  return 0;
}
