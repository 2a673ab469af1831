// CAN bus load of CiA 402 CSP, computed from the frames actually sent on
// the in-process bus while a job runs: every frame's bits with worst-case
// bit stuffing (standard 11-bit frames, hal::canopen::worst_case_bits), per
// second of bus time, against a 1 Mbit/s budget. 2 and 3 axes at 1 ms and
// 2 ms SYNC. The frames/s sustained through the VM bench (real vcan0) is
// printed by ctest's hil_vcan into build/host/hil-out/console.log.
#include <cstdio>
#include <memory>
#include <string>

#include "kerf/hal/can/canopen_master.hpp"
#include "kerf/hal/can/csp_segment_link.hpp"
#include "kerf/hal/canopen.hpp"
#include "kerf/sim/can/virtual_can_bus.hpp"

namespace {

using namespace kerf;

struct Load {
  double frames_per_s = 0.0;
  double bits_per_s = 0.0;
  double expected_bits_per_s = 0.0;  // the cyclic frames alone, from the mapping
};

bool measure(std::size_t axes, std::uint32_t sync_ms, Load& out) {
  sim::VirtualCanBus bus(4096);
  hal::CanOpenConfig cfg;
  cfg.nodes.clear();
  for (std::size_t i = 0; i < axes; ++i) {
    sim::DriveConfig d;
    d.node = static_cast<std::uint8_t>(i + 1);
    bus.add_drive(d);
    cfg.nodes.push_back(d.node);
  }
  cfg.sync_us = sync_ms * 1000;
  std::string err;
  auto master = hal::CanOpenMaster::create(bus.master(), cfg, err);
  if (!master || master->bring_up() != hal::AxisError::none || master->enable() != hal::AxisError::none) {
    std::fprintf(stderr, "bench_can_load: %s\n", master ? master->last_error() : err.c_str());
    return false;
  }
  auto link = hal::CspSegmentLink::create(*master, {}, err);
  if (!link) {
    std::fprintf(stderr, "bench_can_load: %s\n", err.c_str());
    return false;
  }
  // A job long enough for 2 s of motion: a square of 50 mm sides at 100 mm/s.
  hal::BoardStatus st;
  const Vec2<double> corners[] = {{50, 0}, {50, 50}, {0, 50}, {0, 0}};
  for (std::uint32_t k = 1; k <= 4; ++k) {
    hal::SegmentCommand s;
    s.seq = k;
    s.end = corners[k - 1];
    s.feed = 100.0;
    link->push(s, st);
  }
  link->command(hal::Command::start);
  link->command(hal::Command::finish);
  const std::size_t first = bus.log().size();
  const std::uint64_t t0 = bus.now_us();
  while (st.state != hal::BoardState::done && st.state != hal::BoardState::fault) {
    link->cycle();
    link->status(st);
  }
  const std::uint64_t t1 = bus.now_us();
  if (st.state != hal::BoardState::done || t1 <= t0) {
    std::fprintf(stderr, "bench_can_load: the job did not finish: %s\n", link->last_error());
    return false;
  }
  std::uint64_t bits = 0, frames = 0;
  for (std::size_t i = first; i < bus.log().size(); ++i) {
    bits += hal::canopen::worst_case_bits(bus.log()[i].frame.dlc);
    ++frames;
  }
  const double secs = static_cast<double>(t1 - t0) * 1e-6;
  out.frames_per_s = static_cast<double>(frames) / secs;
  out.bits_per_s = static_cast<double>(bits) / secs;
  const double per_sync = 2.0 * static_cast<double>(axes) * hal::canopen::worst_case_bits(6) +
                          hal::canopen::worst_case_bits(0);
  out.expected_bits_per_s = per_sync / (sync_ms * 1e-3);
  return true;
}

}  // namespace

int main() {
  constexpr double kBudget = 1e6;  // 1 Mbit/s
  std::printf("CANopen CSP bus load, worst-case bit stuffing, 1 Mbit/s budget\n");
  std::printf("(frames sent while a 200 mm job runs: RPDO + SYNC + TPDO per cycle, heartbeats)\n\n");
  std::printf("axes  SYNC   frames/s   bits/s     cyclic-only bits/s  load of 1 Mbit/s\n");
  bool ok = true;
  for (std::size_t axes : {2u, 3u})
    for (std::uint32_t ms : {1u, 2u}) {
      Load l;
      if (!measure(axes, ms, l)) return 1;
      const double pct = 100.0 * l.bits_per_s / kBudget;
      std::printf("%4zu  %2u ms  %8.0f  %9.0f  %18.0f  %6.1f %%%s\n", axes, ms, l.frames_per_s, l.bits_per_s,
                  l.expected_bits_per_s, pct, pct > 100.0 ? "  OVER BUDGET" : "");
      ok = ok && l.bits_per_s >= l.expected_bits_per_s;
    }
  if (!ok) {
    std::fprintf(stderr, "bench_can_load: fewer bits than the cyclic frames alone need: frames were lost\n");
    return 1;
  }
  return 0;
}
