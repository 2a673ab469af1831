// A motion board's firmware core on a Cortex-M: core/motion's board executor
// over the interpolator, in static storage, runs a small job (a square with a
// half circle on one side, the torch on for the cut segments) to done and
// prints where it stopped, what ran and how many periods the torch was on.
// The test compares the lines with the host's figures; kerf::Fixed always,
// double too where there is an FPU (not KERF_MCU_FIXED_ONLY, the M0 build).
#include <cstdint>
#include <cstdio>

#include "kerf/core/fixed.hpp"
#include "kerf/motion/board_executor.hpp"
#include "kerf/motion/interpolator_motion.hpp"

namespace {

template <class S>
struct Storage {
  kerf::motion::QueuedSegment<S> slots[8];
  kerf::motion::BoardSegment<S> queue[4];
  S window[4];  // the S-curve's (unused with jerk 0)
};

Storage<kerf::Fixed> fixed_storage;
#ifndef KERF_MCU_FIXED_ONLY
Storage<double> double_storage;
#endif

template <class S>
kerf::motion::BoardSegment<S> segment(std::uint32_t seq, int x, int y, bool torch) {
  kerf::motion::BoardSegment<S> s;
  s.seq = seq;
  s.end = {S(x), S(y)};
  s.feed = S(50);
  s.torch = torch;
  return s;
}

template <class S>
int run(const char* name, Storage<S>& st) {
  using namespace kerf::motion;
  InterpolatorMotion<S> stage{kerf::Span<QueuedSegment<S>>(st.slots), kerf::Span<S>(st.window)};
  MotionConfig<S> c;
  c.period = S(0.001);
  c.accel = S(2000);
  c.corner_angle = S(0.05);
  c.counts_per_mm = {S(1000), S(1000)};
  if (stage.configure(c) != kerf::Status::ok) return 1;
  BoardExecutor<S, InterpolatorMotion<S>> board(stage, kerf::Span<BoardSegment<S>>(st.queue), {});
  BoardSegment<S> job[5] = {segment<S>(1, 10, 0, false), segment<S>(2, 10, 10, true),
                            segment<S>(3, 0, 10, true), segment<S>(4, 0, 0, true), segment<S>(5, 5, 5, false)};
  job[1].kind = kerf::SegmentKind::arc;  // a half circle to the right of x = 10
  job[1].centre = {S(10), S(5)};
  job[1].dir = 1;
  board.command(BoardCommand::start);
  unsigned next = 0, torch = 0, periods = 0, ran = 0;
  while (board.state() == BoardState::running && periods < 100000) {
    while (next < 5 && board.accept(job[next]) == BoardAccept::queued) ++next;
    if (next == 5) board.command(BoardCommand::finish);
    const BoardStep<S> e = board.step();
    ran += e.completed_to - e.completed_from;
    torch += e.torch ? 1u : 0u;
    ++periods;
  }
  const Counts at = stage.counts();
  std::printf("board %s: %s at %ld %ld counts, ran %u, torch %u periods\n", name,
              board.state() == BoardState::done ? "done" : "stuck", static_cast<long>(at.x),
              static_cast<long>(at.y), ran, torch);
  return 0;
}

}  // namespace

int main() {
#ifndef KERF_MCU_FIXED_ONLY
  if (run<double>("double", double_storage) != 0) return 1;
#endif
  return run<kerf::Fixed>("fixed", fixed_storage);
}
