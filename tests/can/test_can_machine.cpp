// The controller on CiA 402 drives (simulated/can_sim_machine.hpp), in
// lockstep with the in-process bus: the same job as the Modbus machine tests
// cuts every segment once; each CAN fault stops it with the torch off and a
// reason naming the drive, and the report keeps the last completed segment.
#include <gtest/gtest.h>

#include "can_jobs.hpp"
#include "simulated/can_sim_machine.hpp"

namespace kerf::test {
namespace {

using control::State;

TEST(CanMachine, CutsEveryPathOnceOverCsp) {
  FakeGpio gpio;
  simulated::CanMachineConfig m;
  m.can.axes = 3;
  const auto r = simulated::run_can_sim_machine(two_paths(), fast_cut(), m, gpio, nullptr, {});
  ASSERT_EQ(r.setup_error, "");
  EXPECT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.executed, (std::vector<std::int64_t>{0, 1, 2, 3}));
  EXPECT_EQ(r.run.pierces, 2u);
  EXPECT_EQ(r.board.state, hal::BoardState::done);
  EXPECT_DOUBLE_EQ(r.run.stopped_at.x, 100.0);
  EXPECT_DOUBLE_EQ(r.run.stopped_at.y, 0.0);
  ASSERT_EQ(gpio.changes.size(), 4u);  // on, off, on, off
}

class CanMachineFault : public ::testing::TestWithParam<simulated::CanFaultKind> {};

TEST_P(CanMachineFault, StopsWithTheTorchOffAndTheDriveNamed) {
  FakeGpio gpio;
  simulated::CanMachineConfig m;
  m.faults = {{GetParam(), 2.4}};  // during the second path (it pierces at about 2.1 s)
  const auto r = simulated::run_can_sim_machine(two_paths(), fast_cut(), m, gpio, nullptr, {});
  ASSERT_EQ(r.setup_error, "");
  EXPECT_EQ(r.run.state, State::fault) << r.run.reason;
  EXPECT_EQ(r.board.state, hal::BoardState::fault);
  EXPECT_EQ(r.run.last_completed, 1) << r.run.reason;  // the first path
  ASSERT_FALSE(gpio.changes.empty());
  EXPECT_FALSE(gpio.changes.back().on);
  const bool names = r.run.reason.find("node") != std::string::npos || r.run.reason.find("bus-off") != std::string::npos;
  EXPECT_TRUE(names) << r.run.reason;
  EXPECT_NE(r.run.reason.find("last completed job segment 1"), std::string::npos) << r.run.reason;
  RecordProperty("reason", r.run.reason);
}

INSTANTIATE_TEST_SUITE_P(Kinds, CanMachineFault,
                         ::testing::Values(simulated::CanFaultKind::heartbeat_loss, simulated::CanFaultKind::emcy,
                                           simulated::CanFaultKind::bus_off, simulated::CanFaultKind::enable_refused),
                         [](const auto& i) {
                           std::string n = simulated::to_string(i.param);
                           n.erase(std::remove(n.begin(), n.end(), '-'), n.end());
                           return n;
                         });

}  // namespace
}  // namespace kerf::test
