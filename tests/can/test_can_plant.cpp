// A CanPlant through the lead's run_sim_machine (needs the Modbus build's
// kerf_simulated, which holds run_sim_machine): the same controller, the CAN drives.
#include <gtest/gtest.h>

#include "can_jobs.hpp"
#include "simulated/can_plant.hpp"
#include "simulated/sim_machine.hpp"

namespace kerf::test {
namespace {

using control::State;

TEST(CanPlant, RunSimMachineOnTheCanDrives) {
  std::string err;
  simulated::CanSimOptions o;
  auto plant = simulated::make_can_plant(o, err);
  ASSERT_TRUE(plant) << err;
  EXPECT_DOUBLE_EQ(plant->tick_s(), 0.001);
  FakeGpio gpio;
  simulated::SimMachineConfig m;
  m.faults = {{simulated::BoardFaultKind::drive_fault, 2.4, 0.0}};
  const auto r = simulated::run_sim_machine(two_paths(), fast_cut(), m, *plant, gpio, nullptr, {});
  ASSERT_EQ(r.setup_error, "");
  EXPECT_EQ(r.run.state, State::fault) << r.run.reason;
  EXPECT_EQ(r.run.last_completed, 1);
  EXPECT_TRUE(r.board.faults & hal::kFaultEmcy);
  simulated::BoardFault drop;
  drop.kind = simulated::BoardFaultKind::link_drop;
  EXPECT_FALSE(plant->inject(drop));
}

TEST(CanPlant, AJobRunsToDone) {
  std::string err;
  auto plant = simulated::make_can_plant({}, err);
  ASSERT_TRUE(plant) << err;
  FakeGpio gpio;
  const auto r = simulated::run_sim_machine(two_paths(), fast_cut(), {}, *plant, gpio, nullptr, {});
  ASSERT_EQ(r.setup_error, "");
  EXPECT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.executed, (std::vector<std::int64_t>{0, 1, 2, 3}));
}

}  // namespace
}  // namespace kerf::test
