// The simulated board driving core/motion's interpolator over the Modbus
// link: feed hold brakes on the path and keeps the queue, resume finishes
// the job, abort stops with the torch off. Ticks are driven by hand, so
// nothing depends on timing.
#include <gtest/gtest.h>

#include "kerf/sim/motion_executor.hpp"
#include "link_rig.hpp"

namespace kerf::test {
namespace {

using hal::BoardState;
using hal::LinkError;

struct MotionRig {
  sim::MotionBoard board;
  std::unique_ptr<sim::BoardServer> server;
  std::unique_ptr<hal::ModbusSegmentLink> link;

  static std::unique_ptr<sim::SegmentExecutor> executor() {
    std::string why;
    auto e = sim::make_motion_executor({}, why);
    if (!e) throw std::runtime_error(why);
    return e;
  }
  MotionRig() : board(sim::BoardConfig{}, executor()) {
    std::string err;
    server = sim::BoardServer::start(board, {}, err);
    hal::ModbusConfig cfg;
    cfg.port = server->port();
    link = hal::ModbusSegmentLink::open(cfg, err);
    if (!link) throw std::runtime_error(err);
  }
  // Ticks until pred holds; false after `max` ticks.
  template <class P>
  bool run_until(P pred, int max) {
    for (int i = 0; i < max; ++i) {
      if (pred(board.status())) return true;
      board.tick();
    }
    return pred(board.status());
  }
};

// Four 10 mm lines along x at 50 mm/s: 0.8 s of motion.
void push_job(MotionRig& rig) {
  hal::BoardStatus st;
  for (std::uint32_t k = 1; k <= 4; ++k) {
    hal::SegmentCommand s;
    s.seq = k;
    s.end = {10.0 * k, 0.0};
    s.feed = 50.0;
    ASSERT_EQ(rig.link->push(s, st), LinkError::none) << rig.link->last_error();
  }
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
}

TEST(BoardMotion, RunsAtFeedAndEndsExactlyOnTheLastPoint) {
  MotionRig rig;
  push_job(rig);
  ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::done; }, 5000));
  EXPECT_EQ(rig.board.executed(), one_to(4));
  EXPECT_DOUBLE_EQ(rig.board.status().position.x, 40.0);
  // 40 mm at 50 mm/s is 0.8 s, plus the start and end ramps (2000 mm/s^2: 25 ms each).
  EXPECT_GT(rig.board.sim_time(), 0.8);
  EXPECT_LT(rig.board.sim_time(), 0.9);
}

TEST(BoardMotion, HoldBrakesOnThePathAndResumeFinishes) {
  MotionRig rig;
  push_job(rig);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.position.x > 15.0; }, 5000));
  ASSERT_EQ(rig.link->command(hal::Command::hold), LinkError::none);
  for (int i = 0; i < 200; ++i) rig.board.tick();  // 0.2 s: far more than the 25 ms ramp
  const double held_at = rig.board.status().position.x;
  for (int i = 0; i < 100; ++i) rig.board.tick();
  EXPECT_DOUBLE_EQ(rig.board.status().position.x, held_at);  // at rest
  EXPECT_LT(held_at, 15.0 + 0.7);  // braking distance at 50 mm/s: 0.625 mm
  EXPECT_EQ(rig.board.status().state, BoardState::hold);
  ASSERT_EQ(rig.link->command(hal::Command::resume), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::done; }, 5000));
  EXPECT_EQ(rig.board.executed(), one_to(4));
  EXPECT_DOUBLE_EQ(rig.board.status().position.x, 40.0);
}

TEST(BoardMotion, AbortTurnsTheTorchOffAndStopsOnThePath) {
  MotionRig rig;
  push_job(rig);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.position.x > 5.0; }, 5000));
  EXPECT_TRUE(rig.board.status().torch);
  ASSERT_EQ(rig.link->command(hal::Command::abort), LinkError::none);
  EXPECT_FALSE(rig.board.status().torch);
  for (int i = 0; i < 200; ++i) rig.board.tick();
  const hal::BoardStatus s = rig.board.status();
  EXPECT_EQ(s.state, BoardState::fault);
  EXPECT_LT(s.position.x, 5.0 + 0.7);
  EXPECT_DOUBLE_EQ(s.position.y, 0.0);
  EXPECT_EQ(s.last_executed, 0u);
  // After a fault reset the job goes on from where the axes stopped.
  ASSERT_EQ(rig.link->command(hal::Command::fault_reset), LinkError::none);
  hal::BoardStatus st;
  hal::SegmentCommand next;
  next.seq = 5;  // numbering continues: 1..4 were accepted, then dropped by the abort
  next.end = {50.0, 0.0};
  next.feed = 50.0;
  ASSERT_EQ(rig.link->push(next, st), LinkError::none) << rig.link->last_error();
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& b) { return b.state == BoardState::done; }, 5000));
  EXPECT_DOUBLE_EQ(rig.board.status().position.x, 50.0);
  EXPECT_EQ(rig.board.executed(), std::vector<std::uint32_t>{5});
}

TEST(BoardMotion, FaultResetWhileBrakingTakesEffectAtRest) {
  // A controller may reset the fault at once (kerf's does when it takes over
  // a board). The reset is latched: the board stays in fault until the
  // brake is over, then goes idle, and the next segment starts at rest.
  MotionRig rig;
  push_job(rig);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.position.x > 5.0; }, 5000));
  ASSERT_EQ(rig.link->command(hal::Command::abort), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::fault_reset), LinkError::none);
  rig.board.tick();
  EXPECT_EQ(rig.board.status().state, BoardState::fault);  // still braking
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& s) { return s.state == BoardState::idle; }, 5000));
  const double stopped_at = rig.board.status().position.x;
  for (int i = 0; i < 50; ++i) rig.board.tick();
  EXPECT_DOUBLE_EQ(rig.board.status().position.x, stopped_at);  // at rest when idle
  EXPECT_EQ(rig.board.status().faults, 0u);
  hal::BoardStatus st;
  hal::SegmentCommand next;
  next.seq = 5;
  next.end = {50.0, 0.0};
  next.feed = 50.0;
  ASSERT_EQ(rig.link->push(next, st), LinkError::none) << rig.link->last_error();
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
  ASSERT_TRUE(rig.run_until([](const hal::BoardStatus& b) { return b.state == BoardState::done; }, 5000));
  EXPECT_DOUBLE_EQ(rig.board.status().position.x, 50.0);
  EXPECT_EQ(rig.board.executed(), std::vector<std::uint32_t>{5});
}

}  // namespace
}  // namespace kerf::test
