// Z moves in the board executor (core/motion/board_executor.hpp, axis_move.hpp),
// in double and kerf::Fixed: a z item runs alone after the segments before
// it, lands exactly on its end within Z's feed and accel, leaves XY where it
// was, and is counted as a segment (sequence, completion, torch); a board
// without a z axis, or a z item whose XY is not the previous end, faults.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "kerf/core/fixed.hpp"
#include "kerf/core/fixed_convert.hpp"
#include "kerf/motion/board_executor.hpp"
#include "kerf/motion/interpolator_motion.hpp"

namespace kerf::motion {
namespace {

template <class S>
S from_d(double v) {
  if constexpr (std::is_same_v<S, double>) return v;
  else return fixed_from_double(v);
}

template <class S>
double to_d(S v) {
  if constexpr (std::is_same_v<S, double>) return v;
  else return static_cast<double>(v.raw()) / 4294967296.0;
}

constexpr double kPeriod = 0.001, kZFeed = 40, kZAccel = 500;

template <class S>
struct ZRig {
  QueuedSegment<S> slots[8];
  BoardSegment<S> queue[6];
  S window[4]{};
  InterpolatorMotion<S> stage{Span<QueuedSegment<S>>(slots), Span<S>(window)};
  std::optional<BoardExecutor<S, InterpolatorMotion<S>>> exec;
  std::vector<std::uint32_t> completed;
  std::vector<BoardStep<S>> steps;

  explicit ZRig(bool with_z) {
    MotionConfig<S> c;
    c.period = S(kPeriod);
    c.accel = S(2000);
    c.counts_per_mm = {S(1000), S(1000)};
    EXPECT_EQ(stage.configure(c), Status::ok);
    exec.emplace(stage, Span<BoardSegment<S>>(queue), Vec2<S>{});
    if (with_z) exec->configure_z({S(kPeriod), S(kZFeed), S(kZAccel)}, S(5));
  }
  static BoardSegment<S> line(std::uint32_t seq, int x, bool torch = false) {
    BoardSegment<S> s;
    s.seq = seq;
    s.end = {S(x), S(0)};
    s.feed = S(50);
    s.torch = torch;
    return s;
  }
  static BoardSegment<S> zmove(std::uint32_t seq, int x, double z, double feed, bool torch = false) {
    BoardSegment<S> s = line(seq, x, torch);
    s.z_move = true;
    s.z = from_d<S>(z);
    s.feed = from_d<S>(feed);
    return s;
  }
  void run(int n) {
    for (int i = 0; i < n && exec->state() == BoardState::running; ++i) {
      const BoardStep<S> e = exec->step();
      for (std::uint32_t k = e.completed_from + 1; k <= e.completed_to; ++k) completed.push_back(k);
      steps.push_back(e);
    }
  }
};

template <class S>
class BoardZMoveTest : public ::testing::Test {};
using Scalars = ::testing::Types<double, Fixed>;
TYPED_TEST_SUITE(BoardZMoveTest, Scalars);

TYPED_TEST(BoardZMoveTest, RunsAloneAtRestWithinZLimitsAndLandsExactly) {
  using R = ZRig<TypeParam>;
  R r(true);
  auto& e = *r.exec;
  ASSERT_EQ(e.accept(R::line(1, 10)), BoardAccept::queued);
  ASSERT_EQ(e.accept(R::zmove(2, 10, -1.5, 100, true)), BoardAccept::queued);  // feed capped at 40
  ASSERT_EQ(e.accept(R::line(3, 20, true)), BoardAccept::queued);
  ASSERT_EQ(e.accept(R::zmove(4, 20, 7.25, 20)), BoardAccept::queued);
  ASSERT_TRUE(e.command(BoardCommand::start));
  ASSERT_TRUE(e.command(BoardCommand::finish));
  r.run(20000);
  ASSERT_EQ(e.state(), BoardState::done);
  EXPECT_EQ(r.completed, (std::vector<std::uint32_t>{1, 2, 3, 4}));
  EXPECT_EQ(e.last_executed(), 4u);
  EXPECT_EQ(to_d(e.z()), 7.25);
  EXPECT_EQ(to_d(e.position().x), 20.0);
  // While a z item runs XY stands still; z moves only then; its speed and
  // acceleration stay within its limits (and the item's own feed).
  double prev_z = 5, prev_v = 0, top = 0;
  Vec2<double> prev_xy{};
  int z_periods = 0;
  for (const BoardStep<TypeParam>& s : r.steps) {
    const double z = to_d(s.z), v = (z - prev_z) / kPeriod;
    const Vec2<double> xy{to_d(s.position.x), to_d(s.position.y)};
    // The period a z item lands in reports it completed (executing is 0 then).
    const auto z_item = [&](std::uint32_t k) {
      return s.executing == k || (s.completed_from < k && k <= s.completed_to);
    };
    if (z_item(2) || z_item(4)) {
      ++z_periods;
      EXPECT_EQ(xy.x, prev_xy.x);
      EXPECT_EQ(xy.y, prev_xy.y);
      if (s.executing != 0) {
        EXPECT_EQ(s.torch, s.executing == 2);
      }
      EXPECT_TRUE(s.thc_lock);
      EXPECT_LE(std::abs(v), (z_item(2) ? kZFeed : 20.0) * (1 + 1e-6));
    } else if (z != prev_z) {
      ADD_FAILURE() << "z moved outside a z item, during " << s.executing;
    }
    EXPECT_LE(std::abs(v - prev_v), kZAccel * kPeriod * (1 + 1e-6)) << "at z " << z;
    top = std::max(top, std::abs(v));
    prev_z = z;
    prev_v = v;
    prev_xy = xy;
  }
  EXPECT_LE(std::abs(prev_v), kZAccel * kPeriod * (1 + 1e-6));  // then at rest
  EXPECT_GT(top, 39.0);  // the 6.5 mm plunge reaches the capped feed
  // 6.5 mm at 40 mm/s with 0.08 s ramps, then 8.75 mm at 20 mm/s with 0.04 s ramps.
  EXPECT_NEAR(z_periods, 242 + 478, 4);
}

TYPED_TEST(BoardZMoveTest, HoldStopsTheZMoveAndResumeFinishesIt) {
  using R = ZRig<TypeParam>;
  R r(true);
  auto& e = *r.exec;
  ASSERT_EQ(e.accept(R::zmove(1, 0, 0, 40)), BoardAccept::queued);
  ASSERT_TRUE(e.command(BoardCommand::start));
  ASSERT_TRUE(e.command(BoardCommand::finish));
  r.run(60);
  ASSERT_EQ(e.executing(), 1u);
  ASSERT_TRUE(e.command(BoardCommand::hold));
  for (int i = 0; i < 200; ++i) e.step();
  const double held = to_d(e.z());
  EXPECT_GT(held, 0.0);
  EXPECT_LT(held, 5.0);
  EXPECT_FALSE(e.moving());
  e.step();
  EXPECT_EQ(to_d(e.z()), held);
  ASSERT_TRUE(e.command(BoardCommand::resume));
  r.run(2000);
  EXPECT_EQ(e.state(), BoardState::done);
  EXPECT_EQ(to_d(e.z()), 0.0);
  EXPECT_EQ(r.completed, (std::vector<std::uint32_t>{1}));
}

// Line 1 to x = 10, then a z move whose XY is x_of_z: refused (bad segment)
// after line 1, z where it stood (0 without a z axis, its start 5 with one).
TYPED_TEST(BoardZMoveTest, RefusedWithoutAZAxisOrOffTheXyEnd) {
  using R = ZRig<TypeParam>;
  for (const bool with_z : {false, true}) {
    R r(with_z);
    auto& e = *r.exec;
    ASSERT_EQ(e.accept(R::line(1, 10)), BoardAccept::queued);
    ASSERT_EQ(e.accept(R::zmove(2, with_z ? 11 : 10, 1, 10)), BoardAccept::queued);
    ASSERT_TRUE(e.command(BoardCommand::start));
    r.run(5000);
    EXPECT_EQ(e.state(), BoardState::fault) << with_z;
    EXPECT_EQ(e.faults(), kBoardFaultBadSegment);
    EXPECT_EQ(r.completed, (std::vector<std::uint32_t>{1}));
    EXPECT_EQ(to_d(e.z()), with_z ? 5.0 : 0.0);
  }
}

TYPED_TEST(BoardZMoveTest, AnAbortBrakesZAndTheNextRunStartsThere) {
  using R = ZRig<TypeParam>;
  R r(true);
  auto& e = *r.exec;
  ASSERT_EQ(e.accept(R::zmove(1, 0, 25, 40)), BoardAccept::queued);
  ASSERT_TRUE(e.command(BoardCommand::start));
  r.run(200);
  ASSERT_TRUE(e.command(BoardCommand::abort));
  ASSERT_TRUE(e.command(BoardCommand::fault_reset));
  for (int i = 0; i < 500 && e.state() == BoardState::fault; ++i) e.step();
  ASSERT_EQ(e.state(), BoardState::idle);
  const double stopped = to_d(e.z());
  EXPECT_GT(stopped, 5.0);
  EXPECT_LT(stopped, 25.0);
  ASSERT_EQ(e.accept(R::zmove(2, 0, 3, 40)), BoardAccept::queued);
  ASSERT_TRUE(e.command(BoardCommand::start));
  ASSERT_TRUE(e.command(BoardCommand::finish));
  r.run(5000);
  EXPECT_EQ(e.state(), BoardState::done);
  EXPECT_EQ(to_d(e.z()), 3.0);
}

}  // namespace
}  // namespace kerf::motion
