// The demo job over CANopen CSP on the in-process bus: the drives' actual
// positions stay within one count of the fitted path (so within tol + 1
// count of the job's points), every SYNC carries its setpoints, the status
// reports like the motion board's (credit, sequence numbers, duplicates,
// hold and resume on the path).
#include <cmath>

#include "can_rig.hpp"
#include "csp_job.hpp"

namespace kerf::test {
namespace {

using hal::BoardState;
using hal::LinkError;
using namespace hal::canopen;

constexpr double kCount = 1e-3;  // mm per count (1000 counts/mm)

// Every SYNC after the first has exactly one RPDO per node before it.
void expect_setpoint_every_sync(const std::vector<sim::LoggedFrame>& log, int nodes) {
  std::vector<int> since(static_cast<std::size_t>(nodes) + 1, 0);
  std::size_t syncs = 0, bad = 0;
  for (const auto& l : log) {
    if (!l.from_master) continue;
    if ((l.frame.id & 0x780) == kRpdo1) ++since[l.frame.id & 0x7F];
    if (l.frame.id == kSync) {
      ++syncs;
      for (int n = 1; n <= nodes; ++n) {
        if (since[static_cast<std::size_t>(n)] != 1) ++bad;
        since[static_cast<std::size_t>(n)] = 0;
      }
    }
  }
  EXPECT_GT(syncs, 0u);
  EXPECT_EQ(bad, 0u) << "SYNC cycles without exactly one setpoint per drive";
}

struct DemoRun {
  DemoJob job;
  double worst_path = 0.0;    // mm, the drives' actual positions to the fitted path
  double worst_points = 0.0;  // mm, to the job's polyline
};

// Runs the demo job to done on a rig whose drives lag by `lag_alpha`.
void run_demo(double lag_alpha, DemoRun& out) {
  DemoJob job = demo_job(250.0);
  const Vec2<double> s0 = job.path.front().start;
  CspRig rig(2, 1000, static_cast<std::int32_t>(std::lround(s0.x * 1000)),
             static_cast<std::int32_t>(std::lround(s0.y * 1000)), lag_alpha);
  std::size_t next = push_some(*rig.link, job.segments, 0);
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  hal::BoardStatus st;
  bool finished = false;
  for (int i = 0; i < 200000; ++i) {
    rig.link->cycle();
    next = push_some(*rig.link, job.segments, next);
    if (next == job.segments.size() && !finished) {
      ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
      finished = true;
    }
    rig.link->status(st);
    if (st.state == BoardState::done || st.state == BoardState::fault) break;
  }
  ASSERT_EQ(st.state, BoardState::done) << rig.link->last_error();
  const auto n = static_cast<std::uint32_t>(job.segments.size());
  EXPECT_EQ(st.last_executed, n);
  std::vector<std::uint32_t> all(n);
  for (std::uint32_t k = 0; k < n; ++k) all[k] = k + 1;
  EXPECT_EQ(rig.link->executed(), all);
  ASSERT_EQ(rig.link->trace().size(), rig.link->trace_total()) << "the trace ring wrapped: part of the job unchecked";
  for (const auto& s : rig.link->trace()) {
    const Vec2<double> p{s.actual[0] * kCount, s.actual[1] * kCount};
    out.worst_path = std::max(out.worst_path, distance_to_path(job.path, p));
    out.worst_points = std::max(out.worst_points, distance_to_polyline(job.points.points, p));
  }
  const Vec2<double> end = job.path.back().end;
  EXPECT_NEAR(st.position.x, end.x, kCount);
  EXPECT_NEAR(st.position.y, end.y, kCount);
  expect_setpoint_every_sync(rig.bus.log(), 2);
  out.job = job;
}

TEST(CanCsp, DemoJobStaysOnTheFittedPathAndEverySyncHasItsSetpoint) {
  DemoRun r;
  ASSERT_NO_FATAL_FAILURE(run_demo(1.0, r));
  EXPECT_LE(r.worst_path, kCount + 1e-9);
  EXPECT_LE(r.worst_points, r.job.tol + kCount + 1e-9);
  RecordProperty("worst_path_nm", static_cast<int>(std::lround(r.worst_path * 1e6)));
}

// The check above can fail: drives whose plant closes only a fifth of the
// gap per SYNC cut inside the arcs by more than a count.
TEST(CanCsp, TheTraceCheckSeesASluggishPlant) {
  DemoRun r;
  ASSERT_NO_FATAL_FAILURE(run_demo(0.2, r));
  EXPECT_GT(r.worst_path, kCount);
}

// Two 10 mm lines along x at 50 mm/s.
void push_lines(CspRig& rig, std::uint32_t count) {
  hal::BoardStatus st;
  for (std::uint32_t k = 1; k <= count; ++k) {
    hal::SegmentCommand s;
    s.seq = k;
    s.end = {10.0 * k, 0.0};
    s.feed = 50.0;
    ASSERT_EQ(rig.link->push(s, st), LinkError::none) << rig.link->last_error();
  }
}

TEST(CanCsp, SequenceNumbersAreIdempotentAndCreditIsTheFreeQueue) {
  CspRig rig;
  hal::BoardStatus st;
  rig.link->status(st);
  const std::uint16_t credit = st.credit;
  push_lines(rig, 2);
  rig.link->status(st);
  EXPECT_EQ(st.credit, credit - 2);
  EXPECT_EQ(st.last_accepted, 2u);
  hal::SegmentCommand again;
  again.seq = 2;
  again.end = {20.0, 0.0};
  again.feed = 50.0;
  EXPECT_EQ(rig.link->push(again, st), LinkError::none);  // a resend: dropped, counted
  EXPECT_EQ(st.duplicates, 1u);
  EXPECT_EQ(st.credit, credit - 2);
  hal::SegmentCommand gap = again;
  gap.seq = 4;
  EXPECT_EQ(rig.link->push(gap, st), LinkError::rejected);
  EXPECT_NE(std::string(rig.link->last_error()).find("gap"), std::string::npos);
}

TEST(CanCsp, HoldBrakesOnThePathAndResumeFinishes) {
  CspRig rig;
  push_lines(rig, 4);
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.position.x > 15.0; }, 5000));
  ASSERT_EQ(rig.link->command(hal::Command::hold), LinkError::none);
  for (int i = 0; i < 200; ++i) rig.link->cycle();
  hal::BoardStatus st;
  rig.link->status(st);
  const double held = st.position.x;
  for (int i = 0; i < 100; ++i) rig.link->cycle();
  rig.link->status(st);
  EXPECT_EQ(st.position.x, held);  // at rest
  EXPECT_EQ(st.position.y, 0.0);   // on the path
  // Braking distance at 50 mm/s and 2000 mm/s^2: 0.625 mm; the feedback the
  // hold was triggered on lags the command by two SYNCs (0.1 mm at 50 mm/s).
  EXPECT_LT(held, 15.0 + 0.1 + 0.625 + 0.05);
  EXPECT_EQ(st.state, BoardState::hold);
  ASSERT_EQ(rig.link->command(hal::Command::resume), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::done; }, 5000));
  rig.link->status(st);
  EXPECT_DOUBLE_EQ(st.position.x, 40.0);
  EXPECT_EQ(st.last_executed, 4u);
}

// The clock thread, as fast as the job allows: it runs only while the queue
// is full or finished, so the host's pace cannot starve the drives.
TEST(CanCsp, ClockThreadRunsTheJobAsTheHostFeedsIt) {
  CspRig rig;
  rig.link->run_clock(false);
  hal::BoardStatus st;
  std::uint32_t seq = 0;
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  while (seq < 100) {  // more segments than the queue holds: pushed on credit
    ASSERT_TRUE(rig.link->wait_until([](const hal::BoardStatus& s) { return s.credit > 0; }, 30.0));
    hal::SegmentCommand s;
    s.seq = ++seq;
    s.end = {1.0 * seq, seq % 2 == 0 ? 0.0 : 0.5};
    s.feed = 100.0;
    ASSERT_EQ(rig.link->push(s, st), LinkError::none) << rig.link->last_error();
  }
  ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
  ASSERT_TRUE(rig.link->wait_until([](const hal::BoardStatus& s) { return s.state == BoardState::done; }, 30.0))
      << rig.link->last_error();
  rig.link->stop_clock();
  rig.link->status(st);
  EXPECT_EQ(st.last_executed, 100u);
  EXPECT_DOUBLE_EQ(st.position.x, 100.0);
  EXPECT_EQ(st.faults, 0u);
  expect_setpoint_every_sync(rig.bus.log(), 2);
}

TEST(CanCsp, ThreeAxesAtTwoMsTheThirdHoldsItsPosition) {
  CspRig rig(3, 2000, 500);
  push_lines(rig, 2);
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::done; }, 5000));
  EXPECT_EQ(rig.master->axis(2).actual, 500);
  EXPECT_EQ(rig.master->axis(0).actual, 20000);
  expect_setpoint_every_sync(rig.bus.log(), 3);
}

}  // namespace
}  // namespace kerf::test
