// Bring-up checked frame by frame against CiA 301 / CiA 402: NMT reset and
// boot-up, expedited SDO setup one request at a time (PDO mapping only while
// the PDO is off), NMT start before any PDO or SYNC, then the 402 enable
// sequence shutdown -> switch on -> enable operation, each step sent only
// after the drive reported the state the previous step leads to, with the
// targets at the actual positions (no jump). Every SYNC has one RPDO per drive.
#include <map>
#include <utility>
#include <vector>

#include <gtest/gtest-spi.h>

#include "can_rig.hpp"

namespace kerf::test {
namespace {

using namespace hal::canopen;
using hal::AxisError;
using Key = std::pair<std::uint16_t, std::uint8_t>;

struct NodeTrace {
  bool reset_sent = false, booted = false, started = false;
  bool sdo_open = false;
  Key open{};
  std::map<Key, std::uint32_t> od;          // last value written
  std::vector<std::uint16_t> controlwords;  // distinct consecutive values sent
  DriveState reported = DriveState::not_ready;
  bool reported_seen = false;
  int rpdos_since_sync = 0;
};

// Walks the log and checks every frame against the rules; returns the
// per-node traces for the final checks.
std::map<int, NodeTrace> check_log(const std::vector<sim::LoggedFrame>& log, int nodes, std::int32_t start) {
  std::map<int, NodeTrace> t;
  int syncs = 0;
  for (std::size_t k = 0; k < log.size(); ++k) {
    const hal::CanFrame& f = log[k].frame;
    SCOPED_TRACE("frame " + std::to_string(k) + " " + sim::candump_line(log[k].t_us, "vcan", f));
    const int fn = static_cast<int>(f.id & 0x780);
    const int n = static_cast<int>(f.id & 0x7F);
    if (log[k].from_master) {
      if (f.id == kNmt) {
        EXPECT_EQ(f.dlc, 2);
        NodeTrace& nt = t[f.data[1]];
        if (f.data[0] == kNmtResetNode) {
          EXPECT_FALSE(nt.started);
          nt.reset_sent = true;
        } else {
          EXPECT_EQ(f.data[0], kNmtStart);
          EXPECT_TRUE(nt.booted) << "NMT start before the boot-up message";
          EXPECT_FALSE(nt.sdo_open) << "NMT start with an SDO transfer open";
          nt.started = true;
        }
      } else if (f.id == kSync) {
        EXPECT_EQ(f.dlc, 0);
        for (int i = 1; i <= nodes; ++i) {
          EXPECT_TRUE(t[i].started) << "SYNC before node " << i << " was started";
          EXPECT_EQ(t[i].rpdos_since_sync, 1) << "node " << i << ": RPDOs before SYNC " << syncs;
          t[i].rpdos_since_sync = 0;
        }
        ++syncs;
      } else if (fn == 0x600) {
        NodeTrace& nt = t[n];
        EXPECT_TRUE(nt.booted) << "SDO before boot-up";
        EXPECT_FALSE(nt.sdo_open) << "a second SDO request before the reply";
        EXPECT_EQ(f.dlc, 8);
        nt.sdo_open = true;
        nt.open = {get_u16(f.data + 1), f.data[3]};
        if (f.data[0] != kSdoUpload) {
          const int size = 4 - ((f.data[0] >> 2) & 3);
          EXPECT_TRUE(f.data[0] == kSdoDownload1 || f.data[0] == kSdoDownload2 || f.data[0] == kSdoDownload4);
          std::uint32_t v = 0;
          for (int i = 0; i < size; ++i) v |= std::uint32_t{f.data[4 + i]} << (8 * i);
          // A mapping changes only while its PDO is switched off (COB-ID bit 31).
          const Key rpdo_comm{kRpdo1Comm, 1}, tpdo_comm{kTpdo1Comm, 1}, count{nt.open.first, 0};
          if (nt.open.first == kRpdo1Map) {
            EXPECT_TRUE(nt.od[rpdo_comm] & kPdoInvalid);
          }
          if (nt.open.first == kTpdo1Map) {
            EXPECT_TRUE(nt.od[tpdo_comm] & kPdoInvalid);
          }
          if ((nt.open.first == kRpdo1Map || nt.open.first == kTpdo1Map) && nt.open.second > 0) {
            EXPECT_EQ(nt.od[count], 0u) << "entries written with the entry count not 0";
          }
          nt.od[nt.open] = v;
        }
      } else if (fn == 0x200) {
        NodeTrace& nt = t[n];
        EXPECT_TRUE(nt.started) << "RPDO before NMT start";
        EXPECT_EQ(f.dlc, 6);
        ++nt.rpdos_since_sync;
        const std::uint16_t cw = get_u16(f.data);
        const auto target = static_cast<std::int32_t>(get_u32(f.data + 2));
        EXPECT_EQ(target, start) << "a target away from the actual position while enabling";
        if (nt.controlwords.empty() || nt.controlwords.back() != cw) {
          // Each 402 command only once the drive reports the state the previous one leads to.
          if (cw == kCwSwitchOn) {
            EXPECT_EQ(nt.reported, DriveState::ready_to_switch_on);
          }
          if (cw == kCwEnableOperation) {
            EXPECT_EQ(nt.reported, DriveState::switched_on);
          }
          if (cw == kCwShutdown) {
            EXPECT_EQ(nt.reported, DriveState::switch_on_disabled);
          }
          nt.controlwords.push_back(cw);
        }
      } else {
        ADD_FAILURE() << "unexpected frame from the master";
      }
    } else {
      NodeTrace& nt = t[n];
      if (fn == 0x700) {
        EXPECT_EQ(f.dlc, 1);
        if (f.data[0] == kHbBootUp) {
          EXPECT_TRUE(nt.reset_sent || k == 0 || !nt.booted);
          nt.booted = true;
        }
      } else if (fn == 0x580) {
        EXPECT_TRUE(nt.sdo_open) << "an SDO reply without a request";
        EXPECT_NE(f.data[0], kSdoAbort) << "SDO abort during bring-up";
        EXPECT_EQ((Key{get_u16(f.data + 1), f.data[3]}), nt.open);
        nt.sdo_open = false;
      } else if (fn == 0x180) {
        EXPECT_EQ(f.dlc, 6);
        nt.reported = decode_state(get_u16(f.data));
        nt.reported_seen = true;
        EXPECT_EQ(static_cast<std::int32_t>(get_u32(f.data + 2)), start);
      } else {
        ADD_FAILURE() << "unexpected frame from a drive";
      }
    }
  }
  return t;
}

TEST(CanBringUp, FrameByFrameAgainstCia301And402) {
  constexpr std::int32_t start = 12345;
  CanRig rig(3, 2000, start);
  rig.up();
  const auto t = check_log(rig.bus.log(), 3, start);
  for (int n = 1; n <= 3; ++n) {
    SCOPED_TRACE("node " + std::to_string(n));
    const NodeTrace& nt = t.at(n);
    EXPECT_TRUE(nt.reset_sent && nt.booted && nt.started);
    const auto& od = nt.od;
    EXPECT_EQ(od.at({kModeOfOperation, 0}), 8u);
    EXPECT_EQ(od.at({kInterpolationPeriod, 1}), 2u);  // 2 ms SYNC
    EXPECT_EQ(od.at({kInterpolationPeriod, 2}), 0xFDu);  // 10^-3 s
    EXPECT_EQ(od.at({kRpdo1Map, 0}), 2u);
    EXPECT_EQ(od.at({kRpdo1Map, 1}), 0x60400010u);
    EXPECT_EQ(od.at({kRpdo1Map, 2}), 0x607A0020u);
    EXPECT_EQ(od.at({kTpdo1Map, 0}), 2u);
    EXPECT_EQ(od.at({kTpdo1Map, 1}), 0x60410010u);
    EXPECT_EQ(od.at({kTpdo1Map, 2}), 0x60640020u);
    EXPECT_EQ(od.at({kRpdo1Comm, 1}), 0x200u + static_cast<unsigned>(n));  // valid again
    EXPECT_EQ(od.at({kTpdo1Comm, 1}), 0x180u + static_cast<unsigned>(n));
    EXPECT_EQ(od.at({kTpdo1Comm, 2}), 1u);  // synchronous, every SYNC
    EXPECT_GT(od.at({kHeartbeatTime, 0}), 0u);
    EXPECT_EQ(nt.controlwords, (std::vector<std::uint16_t>{0x0000, kCwShutdown, kCwSwitchOn, kCwEnableOperation}));
    EXPECT_EQ(nt.reported, DriveState::operation_enabled);
    EXPECT_EQ(rig.bus.drive(static_cast<std::size_t>(n - 1)).state(), DriveState::operation_enabled);
  }
  EXPECT_EQ(rig.master->counters().unknown_cob, 0u);
  EXPECT_EQ(rig.master->counters().bad_dlc, 0u);
}

TEST(CanBringUp, TheCheckerCatchesAnEnableSentTooEarly) {
  // The frame checker must be able to fail: the same log with the master's
  // first "switch on" moved before the drive's "ready to switch on" report.
  CanRig rig(1, 1000, 0);
  rig.up();
  std::vector<sim::LoggedFrame> log = rig.bus.log();
  std::size_t first_switch_on = 0;
  for (std::size_t k = 0; k < log.size() && first_switch_on == 0; ++k)
    if (log[k].from_master && (log[k].frame.id & 0x780) == 0x200 && get_u16(log[k].frame.data) == kCwSwitchOn)
      first_switch_on = k;
  ASSERT_GT(first_switch_on, 0u);
  std::size_t shutdown = 0;
  for (std::size_t k = 0; k < first_switch_on; ++k)
    if (log[k].from_master && (log[k].frame.id & 0x780) == 0x200 && get_u16(log[k].frame.data) == kCwShutdown) {
      shutdown = k;
      break;
    }
  put_u16(log[shutdown].frame.data, kCwSwitchOn);
  ::testing::TestPartResultArray failures;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &failures);
    check_log(log, 1, 0);
  }
  EXPECT_GT(failures.size(), 0);
}

TEST(CanBringUp, ADriveThatRefusesEnableIsNamed) {
  CanRig rig(2);
  ASSERT_EQ(rig.master->bring_up(), AxisError::none) << rig.master->last_error();
  rig.bus.drive(1).inject(sim::DriveFault::enable_refused, rig.bus.now_us());
  EXPECT_EQ(rig.master->enable(), AxisError::enable_refused);
  const std::string err = rig.master->last_error();
  EXPECT_NE(err.find("axis 1 (node 2)"), std::string::npos) << err;
  EXPECT_NE(err.find("switched on"), std::string::npos) << err;
  EXPECT_EQ(rig.bus.drive(0).state(), DriveState::operation_enabled);
}

TEST(CanBringUp, AMissingDriveTimesOutAtBootUp) {
  sim::VirtualCanBus bus;
  bus.add_drive({});  // node 1 only
  hal::CanOpenConfig cfg;
  cfg.nodes = {1, 2};
  std::string err;
  auto m = hal::CanOpenMaster::create(bus.master(), cfg, err);
  ASSERT_TRUE(m);
  EXPECT_EQ(m->bring_up(), AxisError::timeout);
  EXPECT_NE(std::string(m->last_error()).find("node 2"), std::string::npos) << m->last_error();
}

TEST(CanBringUp, BadConfigurationsAreRefused) {
  sim::VirtualCanBus bus;
  std::string err;
  hal::CanOpenConfig cfg;
  cfg.sync_us = 500;
  EXPECT_FALSE(hal::CanOpenMaster::create(bus.master(), cfg, err));
  EXPECT_NE(err.find("SYNC"), std::string::npos);
  cfg = {};
  cfg.nodes = {1, 1};
  EXPECT_FALSE(hal::CanOpenMaster::create(bus.master(), cfg, err));
  EXPECT_NE(err.find("twice"), std::string::npos);
  cfg.nodes = {0};
  EXPECT_FALSE(hal::CanOpenMaster::create(bus.master(), cfg, err));
}

}  // namespace
}  // namespace kerf::test
