// Soft limits (core/motion/soft_limits.hpp), in double and in kerf::Fixed:
// the extent a segment sweeps (arcs' bulges included), and the board
// executor refusing a segment outside the limits before it moves.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>

#include "kerf/core/fixed.hpp"
#include "kerf/core/fixed_convert.hpp"
#include "kerf/motion/board_executor.hpp"
#include "kerf/motion/interpolator_motion.hpp"
#include "kerf/motion/soft_limits.hpp"

namespace kerf::motion {
namespace {

inline double to_d(double v) { return v; }
inline double to_d(Fixed v) { return to_double(v); }

template <class S>
SoftLimits<S> box(int lo, int hi) {  // x and y both in [lo, hi]
  SoftLimits<S> l;
  l.on[0] = l.on[1] = true;
  l.min[0] = l.min[1] = S(lo);
  l.max[0] = l.max[1] = S(hi);
  return l;
}

template <class S>
BoardSegment<S> arc(std::uint32_t seq, Vec2<S> end, Vec2<S> centre, int dir) {
  BoardSegment<S> s;
  s.seq = seq;
  s.kind = SegmentKind::arc;
  s.end = end;
  s.centre = centre;
  s.dir = static_cast<std::int8_t>(dir);
  s.feed = S(50);
  return s;
}

template <class S>
BoardSegment<S> line(std::uint32_t seq, int x, int y) {
  BoardSegment<S> s;
  s.seq = seq;
  s.end = {S(x), S(y)};
  s.feed = S(50);
  return s;
}

template <class S>
class SoftLimitsTest : public ::testing::Test {};
using Scalars = ::testing::Types<double, Fixed>;
TYPED_TEST_SUITE(SoftLimitsTest, Scalars);

TYPED_TEST(SoftLimitsTest, ExtentTakesTheArcsBulgeNotJustItsEnds) {
  using S = TypeParam;
  const Vec2<S> o{}, a{S(10), S(0)}, b{S(-10), S(0)};
  // Counter-clockwise from (10, 0) to (-10, 0) round (0, 0): through (0, 10).
  const Extent<S> up = segment_extent(a, SegmentKind::arc, b, o, 1);
  EXPECT_EQ(to_d(up.hi.y), 10.0);
  EXPECT_EQ(to_d(up.lo.y), 0.0);
  // Clockwise between the same ends: through (0, -10).
  const Extent<S> down = segment_extent(a, SegmentKind::arc, b, o, -1);
  EXPECT_EQ(to_d(down.lo.y), -10.0);
  EXPECT_EQ(to_d(down.hi.y), 0.0);
  // A quarter from (10, 0) to (0, 10): no axis extreme between its ends but its start.
  const Extent<S> q = segment_extent(a, SegmentKind::arc, Vec2<S>{S(0), S(10)}, o, 1);
  EXPECT_EQ(to_d(q.lo.x), 0.0);
  EXPECT_EQ(to_d(q.hi.x), 10.0);
  EXPECT_EQ(to_d(q.lo.y), 0.0);
  // A full circle reaches every side.
  const Extent<S> full = segment_extent(a, SegmentKind::arc, a, o, -1);
  EXPECT_EQ(to_d(full.lo.x), -10.0);
  EXPECT_EQ(to_d(full.hi.y), 10.0);
  // Ends inside [-10, 9], bulge past 9.
  const SoftLimits<S> l = box<S>(-10, 9);
  EXPECT_TRUE(l.contains(a - Vec2<S>{S(1), S(0)}));
  EXPECT_TRUE(l.contains(segment_extent(Vec2<S>{S(0), S(-5)}, SegmentKind::line, Vec2<S>{S(9), S(9)}, o, 0)));
  // Clockwise from (0, -8) to (0, 8) round the origin: through (-8, 0), inside.
  EXPECT_TRUE(l.contains(segment_extent(Vec2<S>{S(0), S(-8)}, SegmentKind::arc, Vec2<S>{S(0), S(8)}, o, -1)));
  // Counter-clockwise from (0, -9.5) round (0, 0) to (0, 9): ends inside, passes (9.5, 0).
  const Vec2<S> low{S(0), S(-9.5)}, top{S(0), S(9)};
  EXPECT_TRUE(l.contains(low) && l.contains(top));
  EXPECT_FALSE(l.contains(segment_extent(low, SegmentKind::arc, Vec2<S>{S(0), S(9.5)}, o, 1)));
  EXPECT_FALSE(l.contains(up));
}

TYPED_TEST(SoftLimitsTest, UnlimitedAxesTakeAnything) {
  using S = TypeParam;
  SoftLimits<S> l = box<S>(0, 100);
  l.on[1] = false;
  EXPECT_TRUE(l.contains(Vec2<S>{S(50), S(-100000)}));
  EXPECT_FALSE(l.contains(Vec2<S>{S(101), S(0)}));
  EXPECT_TRUE(SoftLimits<S>{}.contains(Vec2<S>{S(-100000), S(100000)}));
}

// The executor over the interpolator stage, limited to [-100, 100] on both axes.
template <class S>
struct Rig {
  QueuedSegment<S> slots[8];
  BoardSegment<S> queue[4];
  S window[4]{};
  InterpolatorMotion<S> stage{Span<QueuedSegment<S>>(slots), Span<S>(window)};
  std::optional<BoardExecutor<S, InterpolatorMotion<S>>> exec;
  Rig() {
    MotionConfig<S> c;
    c.period = S(0.001);
    c.accel = S(2000);
    c.counts_per_mm = {S(1000), S(1000)};
    EXPECT_EQ(stage.configure(c), Status::ok);
    exec.emplace(stage, Span<BoardSegment<S>>(queue), Vec2<S>{});
    exec->set_soft_limits(box<S>(-100, 100));
  }
  // Steps until the executor is at rest in fault (true), at most n periods.
  bool run_to_fault(int n) {
    for (int i = 0; i < n; ++i) {
      exec->step();
      if (exec->state() == BoardState::fault && exec->at_rest()) return true;
    }
    return false;
  }
};

TYPED_TEST(SoftLimitsTest, ExecutorRefusesASegmentPastMaxAfterRunningTheOnesBefore) {
  using S = TypeParam;
  Rig<S> r;
  auto& e = *r.exec;
  ASSERT_EQ(e.accept(line<S>(1, 50, 0)), BoardAccept::queued);
  ASSERT_EQ(e.accept(line<S>(2, 101, 0)), BoardAccept::queued);  // 1 mm past max
  ASSERT_TRUE(e.command(BoardCommand::start));
  ASSERT_TRUE(e.command(BoardCommand::finish));
  // The stage takes segment 1, then refuses 2 the moment it would hand it
  // over: the fault brakes segment 1 on the path.
  ASSERT_TRUE(r.run_to_fault(20000));
  EXPECT_EQ(e.faults() & kBoardFaultSoftLimit, kBoardFaultSoftLimit);
  EXPECT_FALSE(e.torch());
  EXPECT_LE(to_d(e.position().x), 50.0);
  EXPECT_EQ(to_d(e.position().y), 0.0);
}

TYPED_TEST(SoftLimitsTest, ExecutorRefusesAnArcWhoseBulgeLeavesTheLimitsBeforeMoving) {
  using S = TypeParam;
  Rig<S> r;
  auto& e = *r.exec;
  // A line to (80, -60), then counter-clockwise round (10, 0) to (80, 60):
  // both ends inside, the arc passes x = 10 + 92.2.
  ASSERT_EQ(e.accept(line<S>(1, 80, -60)), BoardAccept::queued);
  ASSERT_EQ(e.accept(arc<S>(2, Vec2<S>{S(80), S(60)}, Vec2<S>{S(10), S(0)}, 1)), BoardAccept::queued);
  ASSERT_TRUE(e.command(BoardCommand::start));
  e.step();  // the stage takes both at once (8 slots): the arc is refused before anything moves
  EXPECT_EQ(e.state(), BoardState::fault);
  EXPECT_EQ(e.faults(), kBoardFaultSoftLimit);
  ASSERT_TRUE(r.run_to_fault(20000));
  EXPECT_LE(to_d(e.position().x), 80.0);
  EXPECT_EQ(e.last_executed(), 0u);
}

TYPED_TEST(SoftLimitsTest, ExecutorRunsAnArcInsideTheLimits) {
  using S = TypeParam;
  Rig<S> r;
  auto& e = *r.exec;
  // Half a circle counter-clockwise round (40, 0): down to y = -40 and back up.
  ASSERT_EQ(e.accept(arc<S>(1, Vec2<S>{S(80), S(0)}, Vec2<S>{S(40), S(0)}, 1)), BoardAccept::queued);
  ASSERT_TRUE(e.command(BoardCommand::start));
  ASSERT_TRUE(e.command(BoardCommand::finish));
  for (int i = 0; i < 40000 && e.state() != BoardState::done; ++i) e.step();
  EXPECT_EQ(e.state(), BoardState::done);
  EXPECT_EQ(e.faults(), 0u);
}

}  // namespace
}  // namespace kerf::motion
