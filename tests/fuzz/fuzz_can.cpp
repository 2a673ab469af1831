// The CANopen master's frame and SDO decoding (hal/can/canopen_master.hpp)
// on frames a fuzzed bus delivers: bring-up (boot-up heartbeats, SDO
// replies), enable, SYNC cycles and SDO reads, with TPDOs, heartbeats, EMCYs,
// stray and malformed frames in between, at fuzzed times. The master may
// refuse anything, but must not crash, hang or report an error without a
// reason.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"
#include "kerf/hal/can/canopen_master.hpp"
#include "kerf/hal/canopen.hpp"

namespace {

using namespace kerf::hal;
using namespace kerf::hal::canopen;

// A bus whose every received frame, delay and send result comes from the
// fuzz input; when the input runs out it only times out.
class FuzzBus final : public CanBus {
 public:
  explicit FuzzBus(FuzzedDataProvider& in) : in_(in) {}

  CanResult send(const CanFrame& f) override {
    if (f.id >= kSdoRx && f.id < kSdoRx + 0x80) last_sdo_ = f;
    ++counters_.sent;
    if (in_.remaining_bytes() == 0) return CanResult::ok;
    const std::uint8_t r = in_.ConsumeIntegral<std::uint8_t>();
    if (r == 0xFE) return CanResult::queue_full;
    if (r == 0xFF) {
      state_ = BusState::bus_off;
      return CanResult::bus_off;
    }
    return CanResult::ok;
  }

  CanResult receive(CanFrame& f, std::uint64_t until_us) override {
    if (in_.remaining_bytes() < 2) {
      if (until_us > now_) now_ = until_us;
      return CanResult::timeout;
    }
    now_ += in_.ConsumeIntegral<std::uint8_t>() * 50u;
    if (now_ > until_us) {
      now_ = until_us;
      return CanResult::timeout;
    }
    f = CanFrame{};
    const std::uint8_t kind = in_.ConsumeIntegral<std::uint8_t>();
    const std::uint8_t node = static_cast<std::uint8_t>(1 + (kind >> 4) % 3);  // 3: not configured
    switch (kind & 0x0F) {
      case 0:  // an answer to the last SDO request, with a fuzzed command and value
        f = last_sdo_;
        f.id = kSdoTx + (last_sdo_.id & 0x7F);
        f.dlc = 8;
        f.data[0] = in_.ConsumeIntegral<std::uint8_t>();
        for (int i = 4; i < 8; ++i) f.data[i] = in_.ConsumeIntegral<std::uint8_t>();
        break;
      case 1:  // a heartbeat with a fuzzed state (0: boot-up)
        f.id = kHeartbeat + node;
        f.dlc = 1;
        f.data[0] = in_.ConsumeIntegral<std::uint8_t>() % 2 ? kHbOperational : kHbBootUp;
        break;
      case 2:  // a TPDO with a fuzzed statusword and position
        f.id = kTpdo1 + node;
        f.dlc = 6;
        for (int i = 0; i < 6; ++i) f.data[i] = in_.ConsumeIntegral<std::uint8_t>();
        break;
      case 3:
        state_ = static_cast<BusState>(in_.ConsumeIntegral<std::uint8_t>() % 4);
        return CanResult::timeout;
      case 4:
        return CanResult::io_error;
      default: {  // any frame at all
        f.id = in_.ConsumeIntegral<std::uint16_t>() & 0x7FF;
        f.dlc = in_.ConsumeIntegral<std::uint8_t>() % 9;
        for (int i = 0; i < 8; ++i) f.data[i] = in_.ConsumeIntegral<std::uint8_t>();
      }
    }
    ++counters_.received;
    return CanResult::ok;
  }

  std::uint64_t now_us() override { return now_; }
  BusState state() const override { return state_; }
  bool recovered() override {
    if (state_ == BusState::bus_off && in_.ConsumeBool()) state_ = BusState::active;
    return state_ != BusState::bus_off;
  }
  const CanCounters& counters() const override { return counters_; }
  const char* last_error() const override { return "fuzzed I/O error"; }

 private:
  FuzzedDataProvider& in_;
  std::uint64_t now_ = 0;
  BusState state_ = BusState::active;
  CanFrame last_sdo_{};
  CanCounters counters_{};
};

void expect_reason(AxisError e, const CanOpenMaster& m) {
  if (e != AxisError::none) FUZZ_CHECK(m.last_error()[0] != 0, "an error without a reason");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  FuzzBus bus(in);
  CanOpenConfig cfg;
  cfg.nodes = {1, 2};
  cfg.enable_cycles = 8;
  std::string error;
  auto master = CanOpenMaster::create(bus, cfg, error);
  FUZZ_CHECK(master != nullptr, error.c_str());
  AxisError e = master->bring_up();
  expect_reason(e, *master);
  for (int step = 0; step < 64 && in.remaining_bytes() > 0; ++step) {
    switch (in.ConsumeIntegral<std::uint8_t>() % 6) {
      case 0: e = master->enable(); break;
      case 1: e = master->disable(); break;
      case 2: e = master->fault_reset(); break;
      case 3: {
        std::uint32_t v = 0;
        e = master->sdo_read(in.ConsumeIntegral<std::uint8_t>() % 2, kActualPosition, 0, v);
        break;
      }
      default:
        master->set_target(in.ConsumeIntegral<std::uint8_t>() % 2, in.ConsumeIntegral<std::int32_t>());
        e = master->cycle();
    }
    expect_reason(e, *master);
    FUZZ_CHECK(master->counters().cycles <= 64u * 3u * (cfg.enable_cycles + 2u), "runaway cycles");
  }
  return 0;
}
