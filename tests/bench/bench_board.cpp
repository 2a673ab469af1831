// Setpoints per second through a motion board: the simulated board
// (sim::MotionBoard: lock, trace, the executor, the interpolator stage), the
// core board executor alone (double and kerf::Fixed, as a board's firmware
// runs it), and the interpolator alone for reference. The path is collinear
// 2 mm lines at 100 mm/s, 1 ms period: a segment is handed over every 20
// periods, and the host refills the board's 32 slots as credit comes back.
// Prints figures measured in this run; asserts nothing about speed.
//
// usage: kerf_bench_board [--setpoints N]   (default 2e6 per row)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "kerf/core/fixed.hpp"
#include "kerf/motion/board_executor.hpp"
#include "kerf/motion/interpolator_motion.hpp"
#include "kerf/sim/motion_board.hpp"
#include "kerf/sim/motion_executor.hpp"

namespace {

using namespace kerf;
using Clock = std::chrono::steady_clock;

constexpr std::size_t kQueue = 32, kLookahead = 16;

template <class S>
motion::BoardSegment<S> next_line(std::uint32_t seq) {
  motion::BoardSegment<S> s;
  s.seq = seq;
  s.end = {S(static_cast<int>(2 * seq)), S(0)};
  s.feed = S(100);
  return s;
}

double rate(std::uint64_t n, Clock::time_point t0) {
  return static_cast<double>(n) / std::chrono::duration<double>(Clock::now() - t0).count();
}

double sim_board(std::uint64_t n, std::int64_t& check) {
  sim::MotionConfig mc;
  mc.lookahead_slots = kLookahead;
  std::string why;
  sim::BoardConfig bc;
  bc.capacity = kQueue;
  bc.trace_reserve = n + 1;
  sim::MotionBoard board(bc, sim::make_motion_executor(mc, why));
  std::uint32_t seq = 1;
  board.command(static_cast<std::uint16_t>(hal::Command::start));
  const auto t0 = Clock::now();
  for (std::uint64_t k = 0; k < n; ++k) {
    while (board.accept(next_line<double>(seq)) == sim::Accept::queued) ++seq;
    board.tick();
  }
  const double r = rate(n, t0);
  check += static_cast<std::int64_t>(board.status().position.x);
  return r;
}

template <class S>
double core_executor(std::uint64_t n, std::int64_t& check) {
  std::vector<motion::QueuedSegment<S>> slots(kLookahead);
  std::vector<S> window(4);
  std::vector<motion::BoardSegment<S>> queue(kQueue);
  motion::InterpolatorMotion<S> stage({slots.data(), slots.size()}, {window.data(), window.size()});
  motion::MotionConfig<S> c;
  c.period = S(0.001);
  c.accel = S(2000);
  c.corner_angle = S(0.05);
  c.counts_per_mm = {S(1000), S(1000)};
  if (stage.configure(c) != Status::ok) std::abort();
  motion::BoardExecutor<S, motion::InterpolatorMotion<S>> board(stage, {queue.data(), queue.size()}, {});
  board.command(motion::BoardCommand::start);
  std::uint32_t seq = 1;
  const auto t0 = Clock::now();
  for (std::uint64_t k = 0; k < n; ++k) {
    while (board.accept(next_line<S>(seq)) == motion::BoardAccept::queued) ++seq;
    check += board.step().executing;
  }
  return rate(n, t0);
}

double interpolator_alone(std::uint64_t n, std::int64_t& check) {
  std::vector<motion::QueuedSegment<double>> slots(kLookahead);
  motion::Interpolator<double> ip({slots.data(), slots.size()});
  motion::MotionConfig<double> c;
  c.period = 0.001;
  c.accel = 2000;
  c.corner_angle = 0.05;
  c.counts_per_mm = {1000, 1000};
  if (ip.configure(c) != Status::ok) std::abort();
  std::uint32_t seq = 1;
  const auto t0 = Clock::now();
  for (std::uint64_t k = 0; k < n; ++k) {
    while (ip.free_slots() > 0) {
      const double x = 2.0 * seq;
      ip.push({Segment<double>::line({x - 2.0, 0}, {x, 0}), 100.0, seq++});
    }
    check += ip.step().counts.x;
  }
  return rate(n, t0);
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t n = 2000000;
  for (int i = 1; i + 1 < argc; i += 2)
    if (std::strcmp(argv[i], "--setpoints") == 0) n = std::strtoull(argv[i + 1], nullptr, 10);
  std::int64_t check = 0;
  std::printf("motion board, 2 mm lines at 100 mm/s, 1 ms period, queue %zu, look-ahead %zu\n", kQueue, kLookahead);
  std::printf("%-44s %14s\n", "path", "setpoints/s");
  std::printf("%-44s %14.3e\n", "sim::MotionBoard::tick (lock, trace)", sim_board(n, check));
  std::printf("%-44s %14.3e\n", "core BoardExecutor<double>", core_executor<double>(n, check));
  std::printf("%-44s %14.3e\n", "core BoardExecutor<Fixed>", core_executor<Fixed>(n, check));
  std::printf("%-44s %14.3e\n", "core Interpolator<double> alone", interpolator_alone(n, check));
  std::printf("(checksum %lld)\n", static_cast<long long>(check));
  return 0;
}
