// The board executor (core/motion/board_executor.hpp) over the interpolator
// stage, in double and in kerf::Fixed: acceptance by sequence number, credit,
// the command state machine, the fault latched while braking, finish -> done
// and the torch by sequence number.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "kerf/core/fixed.hpp"
#include "kerf/motion/board_executor.hpp"
#include "kerf/motion/interpolator_motion.hpp"

namespace kerf::motion {
namespace {

template <class S>
double to_d(S v) {
  if constexpr (std::is_same_v<S, double>) return v;
  else return static_cast<double>(v.raw()) / 4294967296.0;
}

template <class S>
struct Rig {
  static constexpr std::size_t kQueue = 4;
  QueuedSegment<S> slots[8];
  BoardSegment<S> queue[kQueue];
  S window[4]{};  // the S-curve's (unused with jerk 0)
  InterpolatorMotion<S> stage{Span<QueuedSegment<S>>(slots), Span<S>(window)};
  std::optional<BoardExecutor<S, InterpolatorMotion<S>>> exec;
  std::vector<std::uint32_t> completed;  // in completion order

  Rig() {
    MotionConfig<S> c;
    c.period = S(0.001);
    c.accel = S(2000);
    c.corner_angle = S(0.05);
    c.counts_per_mm = {S(1000), S(1000)};
    EXPECT_EQ(stage.configure(c), Status::ok);
    exec.emplace(stage, Span<BoardSegment<S>>(queue), Vec2<S>{});
  }
  // A line to (x, 0) at 50 mm/s.
  static BoardSegment<S> line(std::uint32_t seq, int x, bool torch = true) {
    BoardSegment<S> s;
    s.seq = seq;
    s.end = {S(x), S(0)};
    s.feed = S(50);
    s.torch = torch;
    return s;
  }
  BoardStep<S> step() {
    const BoardStep<S> e = exec->step();
    for (std::uint32_t k = e.completed_from + 1; k <= e.completed_to; ++k) completed.push_back(k);
    return e;
  }
  // Lines 1 .. n, to (10 k, 0), and start (and finish: no more to come).
  void start_lines(std::uint32_t n, bool finish) {
    for (std::uint32_t k = 1; k <= n; ++k)
      EXPECT_EQ(exec->accept(line(k, 10 * static_cast<int>(k))), BoardAccept::queued) << k;
    EXPECT_TRUE(exec->command(BoardCommand::start));
    if (finish) {
      EXPECT_TRUE(exec->command(BoardCommand::finish));
    }
  }
  // Runs to done; it must end at (x, 0) having completed `want`, in order.
  void expect_done_at(double x, const std::vector<std::uint32_t>& want) {
    ASSERT_TRUE(run_until([&] { return exec->state() == BoardState::done; }, 5000));
    EXPECT_EQ(to_d(exec->position().x), x);
    EXPECT_EQ(to_d(exec->position().y), 0.0);
    EXPECT_EQ(completed, want);
  }
  // Steps until pred holds (true) or n periods pass (false).
  template <class P>
  bool run_until(P pred, int n) {
    for (int i = 0; i < n; ++i) {
      if (pred()) return true;
      step();
    }
    return pred();
  }
};

template <class S>
class BoardExecutorTest : public ::testing::Test {};
using Scalars = ::testing::Types<double, Fixed>;
TYPED_TEST_SUITE(BoardExecutorTest, Scalars);

TYPED_TEST(BoardExecutorTest, AcceptsOnlyTheNextNumberDropsResendsAndCountsCredit) {
  using R = Rig<TypeParam>;
  R r;
  auto& e = *r.exec;
  EXPECT_EQ(e.credit(), R::kQueue);
  EXPECT_EQ(e.accept(R::line(1, 10)), BoardAccept::queued);
  EXPECT_EQ(e.accept(R::line(1, 10)), BoardAccept::duplicate);
  EXPECT_EQ(e.accept(R::line(3, 30)), BoardAccept::gap);
  EXPECT_EQ(e.duplicates(), 1u);
  for (std::uint32_t k = 2; k <= 4; ++k) EXPECT_EQ(e.accept(R::line(k, 10 * static_cast<int>(k))), BoardAccept::queued);
  EXPECT_EQ(e.credit(), 0u);
  EXPECT_EQ(e.accept(R::line(5, 50)), BoardAccept::full);
  EXPECT_EQ(e.last_accepted(), 4u);
  // Idle: nothing runs, so nothing leaves the queue.
  for (int i = 0; i < 10; ++i) EXPECT_FALSE(r.step().stepped);
  EXPECT_EQ(e.credit(), 0u);
  // Running: the stage takes what it has room for, and credit comes back.
  ASSERT_TRUE(e.command(BoardCommand::start));
  r.step();
  EXPECT_EQ(e.credit(), R::kQueue);
  EXPECT_EQ(e.executing(), 1u);
  // After finish nothing more is taken, even the next number.
  ASSERT_TRUE(e.command(BoardCommand::finish));
  EXPECT_EQ(e.accept(R::line(5, 50)), BoardAccept::invalid);
  EXPECT_EQ(e.accept(R::line(2, 20)), BoardAccept::duplicate);
  EXPECT_EQ(e.duplicates(), 2u);
}

TYPED_TEST(BoardExecutorTest, CommandsAreRefusedOutOfTurn) {
  Rig<TypeParam> r;
  auto& e = *r.exec;
  EXPECT_FALSE(e.command(BoardCommand::hold));
  EXPECT_FALSE(e.command(BoardCommand::resume));
  EXPECT_FALSE(e.command(BoardCommand::fault_reset));
  ASSERT_TRUE(e.command(BoardCommand::start));
  EXPECT_FALSE(e.command(BoardCommand::start));
  EXPECT_FALSE(e.command(BoardCommand::resume));
  EXPECT_EQ(e.state(), BoardState::running);
}

TYPED_TEST(BoardExecutorTest, RunsToDoneInOrderWithTheTorchOfEachSegment) {
  using R = Rig<TypeParam>;
  R r;
  auto& e = *r.exec;
  ASSERT_EQ(e.accept(R::line(1, 2, false)), BoardAccept::queued);  // travel
  ASSERT_EQ(e.accept(R::line(2, 4, true)), BoardAccept::queued);   // cut
  ASSERT_EQ(e.accept(R::line(3, 6, false)), BoardAccept::queued);  // travel
  ASSERT_TRUE(e.command(BoardCommand::start));
  ASSERT_TRUE(e.command(BoardCommand::finish));
  std::uint32_t seen_torch = 0, seen_dark = 0;
  for (int i = 0; i < 2000 && e.state() == BoardState::running; ++i) {
    const BoardStep<TypeParam> s = r.step();
    if (s.executing != 0) {
      EXPECT_EQ(s.torch, s.executing == 2) << "segment " << s.executing;
      (s.torch ? seen_torch : seen_dark) += 1;
    }
  }
  EXPECT_EQ(e.state(), BoardState::done);
  EXPECT_FALSE(e.torch());
  EXPECT_EQ(e.executing(), 0u);
  EXPECT_GT(seen_torch, 0u);
  EXPECT_GT(seen_dark, 0u);
  EXPECT_EQ(r.completed, (std::vector<std::uint32_t>{1, 2, 3}));
  EXPECT_EQ(e.last_executed(), 3u);
  EXPECT_EQ(to_d(e.position().x), 6.0);
  EXPECT_EQ(to_d(e.position().y), 0.0);
  EXPECT_FALSE(e.needs_step(true));
  // A new run after done.
  ASSERT_TRUE(e.command(BoardCommand::start));
  EXPECT_EQ(e.accept(R::line(4, 8)), BoardAccept::queued);
}

TYPED_TEST(BoardExecutorTest, HoldBrakesOnThePathAndResumeFinishes) {
  using R = Rig<TypeParam>;
  R r;
  auto& e = *r.exec;
  r.start_lines(2, true);
  ASSERT_TRUE(r.run_until([&] { return to_d(e.position().x) > 5.0; }, 5000));
  const double at_hold = to_d(e.position().x);
  ASSERT_TRUE(e.command(BoardCommand::hold));
  EXPECT_FALSE(e.command(BoardCommand::hold));
  ASSERT_TRUE(r.run_until([&] { return !e.needs_step(true); }, 1000));
  const double held = to_d(e.position().x);
  for (int i = 0; i < 50; ++i) r.step();
  EXPECT_EQ(to_d(e.position().x), held);
  EXPECT_EQ(to_d(e.position().y), 0.0);
  EXPECT_EQ(e.state(), BoardState::hold);
  EXPECT_FALSE(e.torch());
  // 50 mm/s braking at 2000 mm/s^2: 0.625 mm, plus a count of rounding.
  EXPECT_GT(held, at_hold);
  EXPECT_LT(held, at_hold + 0.625 + 0.05 + 0.002);
  ASSERT_TRUE(e.command(BoardCommand::resume));
  EXPECT_TRUE(e.needs_step(true));
  r.expect_done_at(20.0, {1, 2});
}

TYPED_TEST(BoardExecutorTest, TheFaultIsLatchedWhileBrakingAndResetsAtRest) {
  using R = Rig<TypeParam>;
  R r;
  auto& e = *r.exec;
  r.start_lines(4, false);
  ASSERT_TRUE(r.run_until([&] { return to_d(e.position().x) > 15.0; }, 5000));
  ASSERT_TRUE(e.torch());
  ASSERT_TRUE(e.command(BoardCommand::abort));
  EXPECT_EQ(e.state(), BoardState::fault);
  EXPECT_EQ(e.faults(), kBoardFaultAbort);
  EXPECT_FALSE(e.torch());
  EXPECT_EQ(e.executing(), 0u);
  EXPECT_EQ(e.accept(R::line(5, 50)), BoardAccept::invalid);
  // Reset while the axes still brake: latched, the board stays in fault.
  r.step();
  ASSERT_TRUE(e.moving());
  ASSERT_TRUE(e.command(BoardCommand::fault_reset));
  r.step();
  EXPECT_EQ(e.state(), BoardState::fault);
  EXPECT_TRUE(e.needs_step(false));
  ASSERT_TRUE(r.run_until([&] { return e.state() != BoardState::fault; }, 1000));
  EXPECT_EQ(e.state(), BoardState::idle);
  EXPECT_EQ(e.faults(), 0u);
  EXPECT_FALSE(e.moving());
  const double stopped = to_d(e.position().x);
  EXPECT_GT(stopped, 15.0);
  EXPECT_LT(stopped, 15.0 + 0.625 + 0.1);
  EXPECT_EQ(to_d(e.position().y), 0.0);
  // What ran is reported once; what the fault dropped never is.
  const std::uint32_t ran = e.last_executed();
  EXPECT_EQ(ran, 1u);
  // The next run continues from where the axes stopped, numbered after the last accepted.
  ASSERT_EQ(e.accept(R::line(5, 40)), BoardAccept::queued);
  ASSERT_TRUE(e.command(BoardCommand::start));
  ASSERT_TRUE(e.command(BoardCommand::finish));
  r.expect_done_at(40.0, {1, 5});
}

TYPED_TEST(BoardExecutorTest, AResetAtRestIsImmediateAndAFaultAfterItWantsItsOwn) {
  using R = Rig<TypeParam>;
  R r;
  auto& e = *r.exec;
  ASSERT_TRUE(e.command(BoardCommand::abort));  // from idle: at rest already
  EXPECT_EQ(e.state(), BoardState::fault);
  ASSERT_TRUE(e.command(BoardCommand::fault_reset));
  EXPECT_EQ(e.state(), BoardState::idle);
  // A fault while braking after the reset command cancels that reset.
  ASSERT_EQ(e.accept(R::line(1, 10)), BoardAccept::queued);
  ASSERT_TRUE(e.command(BoardCommand::start));
  ASSERT_TRUE(r.run_until([&] { return to_d(e.position().x) > 2.0; }, 5000));
  e.fault(1u << 4);
  ASSERT_TRUE(e.command(BoardCommand::fault_reset));
  e.fault(1u << 5);
  ASSERT_TRUE(r.run_until([&] { return !e.needs_step(true); }, 1000));
  EXPECT_EQ(e.state(), BoardState::fault);
  EXPECT_EQ(e.faults(), (1u << 4) | (1u << 5));
}

TYPED_TEST(BoardExecutorTest, ASegmentTheStageRefusesIsAFault) {
  using R = Rig<TypeParam>;
  R r;
  auto& e = *r.exec;
  ASSERT_EQ(e.accept(R::line(1, 0)), BoardAccept::queued);  // zero length: from (0, 0) to (0, 0)
  ASSERT_TRUE(e.command(BoardCommand::start));
  r.step();
  EXPECT_EQ(e.state(), BoardState::fault);
  EXPECT_EQ(e.faults(), kBoardFaultBadSegment);
  EXPECT_EQ(e.credit(), R::kQueue);  // the queue was dropped
}

// A caller whose drives lag (the CSP link) waits for them before done.
TYPED_TEST(BoardExecutorTest, DoneWaitsForTheDrivesWhenAsked) {
  using R = Rig<TypeParam>;
  R r;
  auto& e = *r.exec;
  ASSERT_EQ(e.accept(R::line(1, 1)), BoardAccept::queued);
  ASSERT_TRUE(e.command(BoardCommand::start));
  ASSERT_TRUE(e.command(BoardCommand::finish));
  for (int i = 0; i < 2000; ++i) e.step(true);
  EXPECT_TRUE(e.at_rest());
  EXPECT_EQ(e.state(), BoardState::running);
  e.drives_settled();
  EXPECT_EQ(e.state(), BoardState::done);
}

// As fast as possible, a running board steps only while its queue holds
// segments or the job is finished; paced, also while the stage is busy.
TYPED_TEST(BoardExecutorTest, NeedsAStepOnlyWhenThereIsWork) {
  using R = Rig<TypeParam>;
  R r;
  auto& e = *r.exec;
  EXPECT_FALSE(e.needs_step(true));
  ASSERT_EQ(e.accept(R::line(1, 10)), BoardAccept::queued);
  EXPECT_FALSE(e.needs_step(true));  // idle
  ASSERT_TRUE(e.command(BoardCommand::start));
  EXPECT_TRUE(e.needs_step(false));
  r.step();  // the segment is in the stage now
  EXPECT_FALSE(e.needs_step(false));
  EXPECT_TRUE(e.needs_step(true));
  ASSERT_TRUE(e.command(BoardCommand::finish));
  EXPECT_TRUE(e.needs_step(false));
}

}  // namespace
}  // namespace kerf::motion
