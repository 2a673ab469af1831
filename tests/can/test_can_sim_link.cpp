// The `kerf sim --link can` entry point (simulated/can_sim_link.hpp) on the
// in-process bus: a job runs to done by ticks, each fault kind ends in a
// fault naming the last completed segment, a drive that refuses enable at
// power-up makes the link fail with the drive named, the candump log is
// written, and bad options are refused. Also SocketCAN's error path on a
// kernel without CAN support (this machine): a clear error, no crash.
#include <fstream>

#include "simulated/can_sim_link.hpp"
#include "kerf/hal/can/socket_can_bus.hpp"
#include "can_rig.hpp"

namespace kerf::test {
namespace {

using simulated::CanFaultKind;
using hal::BoardState;
using hal::LinkError;

void push_lines(hal::SegmentLink& link, std::uint32_t n) {
  hal::BoardStatus st;
  for (std::uint32_t k = 1; k <= n; ++k) {
    hal::SegmentCommand s;
    s.seq = k;
    s.end = {1.0 + 10.0 * k, 2.0};
    s.feed = 100.0;
    ASSERT_EQ(link.push(s, st), LinkError::none) << link.last_error();
  }
  ASSERT_EQ(link.command(hal::Command::start), LinkError::none);
  ASSERT_EQ(link.command(hal::Command::finish), LinkError::none);
}

BoardState run(simulated::CanSimLink& link, int max_ticks) {
  hal::BoardStatus st;
  for (int i = 0; i < max_ticks; ++i) {
    link.status(st);
    if (st.state == BoardState::done || st.state == BoardState::fault) break;
    link.tick();
  }
  link.status(st);
  return st.state;
}

TEST(CanSimLink, RunsAJobAndWritesTheCandumpLog) {
  simulated::CanSimOptions o;
  o.axes = 3;
  o.sync_ms = 2;
  o.start = {1.0, 2.0};
  o.candump_path = ::testing::TempDir() + "can_sim_link.candump";
  std::string err;
  auto link = simulated::make_can_sim_link(o, err);
  ASSERT_TRUE(link) << err;
  EXPECT_DOUBLE_EQ(link->sync_period_s(), 0.002);
  ASSERT_NO_FATAL_FAILURE(push_lines(*link, 3));
  ASSERT_EQ(run(*link, 10000), BoardState::done) << link->last_error();
  hal::BoardStatus st;
  link->status(st);
  EXPECT_DOUBLE_EQ(st.position.x, 31.0);
  EXPECT_DOUBLE_EQ(st.position.y, 2.0);
  // 3 drives at 2 ms: per SYNC 3 RPDOs (6 bytes), SYNC, 3 TPDOs (6 bytes).
  const double per_sync = 6 * hal::canopen::worst_case_bits(6) + hal::canopen::worst_case_bits(0);
  EXPECT_GT(link->bus_load_bps(), per_sync / 0.002);
  EXPECT_LT(link->bus_load_bps(), per_sync / 0.002 * 1.2);  // plus heartbeats and the setup
  ASSERT_TRUE(link->finish_log(err)) << err;
  std::ifstream log(o.candump_path);
  std::string first;
  ASSERT_TRUE(std::getline(log, first));
  EXPECT_EQ(first, "(0.000000) vcan-sim 701#00");  // drive 1's boot-up
}

TEST(CanSimLink, EveryFaultKindStopsWithTheLastSegmentNamed) {
  for (CanFaultKind k : {CanFaultKind::heartbeat_loss, CanFaultKind::emcy, CanFaultKind::bus_off,
                         CanFaultKind::enable_refused}) {
    SCOPED_TRACE(simulated::to_string(k));
    std::string err;
    auto link = simulated::make_can_sim_link({}, err);
    ASSERT_TRUE(link) << err;
    ASSERT_NO_FATAL_FAILURE(push_lines(*link, 4));
    for (int i = 0; i < 200; ++i) link->tick();  // into segment 2 (11.2 mm at 100 mm/s from rest)
    link->inject(k);
    ASSERT_EQ(run(*link, 1000), BoardState::fault);
    hal::BoardStatus st;
    link->status(st);
    EXPECT_GE(st.last_executed, 1u);
    EXPECT_FALSE(st.torch);
    EXPECT_NE(std::string(link->last_error()).find("last completed segment " + std::to_string(st.last_executed)),
              std::string::npos)
        << link->last_error();
    if (k == CanFaultKind::enable_refused) {  // and the reset fails, naming the drive
      for (int i = 0; i < 200; ++i) link->tick();
      ASSERT_EQ(link->command(hal::Command::fault_reset), LinkError::none);
      link->tick();
      link->status(st);
      EXPECT_EQ(st.state, BoardState::fault);
      EXPECT_NE(std::string(link->last_error()).find("node 2): enable refused"), std::string::npos)
          << link->last_error();
    }
  }
}

TEST(CanSimLink, OptionsFromTheMachineConfiguration) {
  config::Config cfg;
  cfg.machine.axes = {{"x", 800.0}, {"y", 1250.0}};
  cfg.machine.accel = 1500.0;
  cfg.link.kind = config::Link::Kind::can;
  cfg.link.node_ids = {5, 9};
  cfg.link.sync_ms = 2;
  const simulated::CanSimOptions o = simulated::can_sim_options(cfg);
  EXPECT_EQ(o.axes, 2u);
  EXPECT_EQ(o.node_ids, (std::vector<std::uint8_t>{5, 9}));
  EXPECT_EQ(o.sync_ms, 2.0);
  EXPECT_EQ(o.counts_per_mm.x, 800.0);
  EXPECT_EQ(o.counts_per_mm.y, 1250.0);
  EXPECT_EQ(o.accel_mm_s2, 1500.0);
  EXPECT_TRUE(o.iface.empty());
}

TEST(CanSimLink, NodeIdsAndCountsPerAxis) {
  simulated::CanSimOptions o;
  o.node_ids = {5, 9};
  o.counts_per_mm = {800.0, 1250.0};
  std::string err;
  auto link = simulated::make_can_sim_link(o, err);
  ASSERT_TRUE(link) << err;
  EXPECT_EQ(link->axes().axis(0).node, 5);
  EXPECT_EQ(link->axes().axis(1).node, 9);
  ASSERT_NO_FATAL_FAILURE(push_lines(*link, 1));
  ASSERT_EQ(run(*link, 5000), BoardState::done) << link->last_error();
  EXPECT_EQ(link->axes().axis(0).actual, 8800);   // 11 mm at 800 counts/mm
  EXPECT_EQ(link->axes().axis(1).actual, 2500);   // 2 mm at 1250 counts/mm
  hal::BoardStatus st;
  link->status(st);
  EXPECT_DOUBLE_EQ(st.position.x, 11.0);
  EXPECT_DOUBLE_EQ(st.position.y, 2.0);
  link->inject(CanFaultKind::heartbeat_loss);  // the last axis: node 9
  for (int i = 0; i < 1000 && st.state != BoardState::fault; ++i) {
    link->tick();  // SYNC keeps running after the job, and so does the heartbeat consumer
    link->status(st);
  }
  ASSERT_EQ(st.state, BoardState::fault);
  EXPECT_NE(std::string(link->last_error()).find("axis 1 (node 9): heartbeat lost"), std::string::npos)
      << link->last_error();
  o.node_ids = {5};
  EXPECT_FALSE(simulated::make_can_sim_link(o, err));
  EXPECT_NE(err.find("one node id per axis"), std::string::npos) << err;
}

TEST(CanSimLink, ADriveRefusingEnableAtPowerUpIsNamed) {
  simulated::CanSimOptions o;
  o.refuse_enable_axis = 1;
  std::string err;
  EXPECT_FALSE(simulated::make_can_sim_link(o, err));
  EXPECT_NE(err.find("axis 1 (node 2): enable refused"), std::string::npos) << err;
}

TEST(CanSimLink, BadOptionsAreRefused) {
  std::string err;
  simulated::CanSimOptions o;
  o.axes = 4;
  EXPECT_FALSE(simulated::make_can_sim_link(o, err));
  EXPECT_NE(err.find("--axes"), std::string::npos);
  o = {};
  o.sync_ms = 11;
  EXPECT_FALSE(simulated::make_can_sim_link(o, err));
  EXPECT_NE(err.find("--sync-ms"), std::string::npos);
  o.sync_ms = 1.5;
  EXPECT_FALSE(simulated::make_can_sim_link(o, err));
  EXPECT_NE(err.find("whole number"), std::string::npos);
  CanFaultKind k{};
  EXPECT_TRUE(simulated::parse_can_fault("bus-off", k));
  EXPECT_EQ(k, CanFaultKind::bus_off);
  EXPECT_FALSE(simulated::parse_can_fault("bus_off", k));
}

TEST(SocketCan, AMissingInterfaceIsAClearError) {
  std::string err;
  EXPECT_FALSE(hal::SocketCanBus::open("kerfnocan0", {}, err));
  EXPECT_NE(err.find("SocketCAN"), std::string::npos) << err;
  EXPECT_FALSE(hal::SocketCanBus::open("", {}, err));
  EXPECT_NE(err.find("bad interface name"), std::string::npos) << err;
}

}  // namespace
}  // namespace kerf::test
