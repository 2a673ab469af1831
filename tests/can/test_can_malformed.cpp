// Frames that do not fit are counted and refused, never trusted: a TPDO or
// heartbeat with the wrong DLC, a COB-ID of no configured node, an SDO reply
// nobody asked for, an SDO abort; on the drive side an RPDO with the wrong
// DLC and an SDO with a bad command or object.
#include "can_rig.hpp"

namespace kerf::test {
namespace {

using hal::AxisError;
using namespace hal::canopen;

hal::CanFrame frame(std::uint32_t id, std::uint8_t dlc, std::initializer_list<std::uint8_t> bytes) {
  hal::CanFrame f;
  f.id = id;
  f.dlc = dlc;
  int i = 0;
  for (std::uint8_t b : bytes) f.data[i++] = b;
  return f;
}

TEST(CanMalformed, MasterCountsAndIgnoresFramesThatDoNotFit) {
  CanRig rig(2, 1000, 100);
  rig.up();
  const auto before = rig.master->counters();
  // A TPDO from node 1 one byte short, claiming a far-away position.
  rig.bus.inject_frame(frame(kTpdo1 + 1, 5, {0x37, 0x02, 0xFF, 0xFF, 0x0F}));
  // A TPDO from node 5, which is not configured, and an id no CANopen node uses here.
  rig.bus.inject_frame(frame(kTpdo1 + 5, 6, {0x37, 0x02, 0, 0, 0, 0}));
  rig.bus.inject_frame(frame(0x3FF, 2, {1, 2}));
  // A heartbeat with two bytes, an SDO reply nobody asked for, a short EMCY.
  rig.bus.inject_frame(frame(kHeartbeat + 2, 2, {0x05, 0x00}));
  rig.bus.inject_frame(frame(kSdoTx + 1, 8, {0x60, 0x40, 0x60, 0, 0, 0, 0, 0}));
  rig.bus.inject_frame(frame(kEmcy + 2, 3, {0x10, 0x23, 0x01}));
  EXPECT_EQ(rig.master->cycle(), AxisError::none) << rig.master->last_error();
  const auto& c = rig.master->counters();
  EXPECT_EQ(c.bad_dlc - before.bad_dlc, 3u);
  EXPECT_EQ(c.unknown_cob - before.unknown_cob, 2u);
  EXPECT_EQ(c.stray_sdo - before.stray_sdo, 1u);
  EXPECT_EQ(c.emcy, before.emcy);
  EXPECT_EQ(rig.master->axis(0).actual, 100) << "a malformed TPDO was trusted";
  EXPECT_EQ(decode_state(rig.master->axis(0).statusword), DriveState::operation_enabled);
}

TEST(CanMalformed, SdoAbortIsCountedAndNamed) {
  CanRig rig(1);
  ASSERT_EQ(rig.master->bring_up(), AxisError::none) << rig.master->last_error();
  EXPECT_EQ(rig.master->sdo_write(0, kModeOfOperation, 0, 3, 1), AxisError::sdo_abort);  // not CSP
  EXPECT_NE(std::string(rig.master->last_error()).find("0x06090030"), std::string::npos) << rig.master->last_error();
  EXPECT_EQ(rig.master->sdo_write(0, 0x2000, 0, 1, 1), AxisError::sdo_abort);  // no such object
  EXPECT_NE(std::string(rig.master->last_error()).find("0x06020000"), std::string::npos);
  EXPECT_EQ(rig.master->sdo_write(0, kStatusword, 0, 1, 2), AxisError::sdo_abort);  // read-only
  EXPECT_NE(std::string(rig.master->last_error()).find("0x06010002"), std::string::npos);
  EXPECT_EQ(rig.master->sdo_write(0, kHeartbeatTime, 0, 1, 4), AxisError::sdo_abort);  // wrong size
  EXPECT_NE(std::string(rig.master->last_error()).find("0x06070010"), std::string::npos);
  // The mapping of a PDO that is on cannot change.
  EXPECT_EQ(rig.master->sdo_write(0, kRpdo1Map, 1, 0x60400010, 4), AxisError::sdo_abort);
  EXPECT_EQ(rig.master->counters().sdo_aborts, 5u);
  EXPECT_EQ(rig.bus.drive(0).counters().sdo_aborts, 5u);
  std::uint32_t mode = 0;
  EXPECT_EQ(rig.master->sdo_read(0, kModeDisplay, 0, mode), AxisError::none);
  EXPECT_EQ(mode, 8u);  // the refused writes changed nothing
}

TEST(CanMalformed, DriveRefusesAnRpdoWithTheWrongLength) {
  CanRig rig(1, 1000, 0);
  rig.up();
  hal::CanBus& m = rig.bus.master();
  const auto bad_before = rig.bus.drive(0).counters().bad_dlc;
  // Controlword + a 3-byte "target": one byte short of the mapping.
  ASSERT_EQ(m.send(frame(kRpdo1 + 1, 5, {0x0F, 0x00, 0x10, 0x27, 0x00})), hal::CanResult::ok);
  ASSERT_EQ(m.send(frame(kSync, 0, {})), hal::CanResult::ok);
  // An SDO of 4 bytes (SDOs are always 8) and an unknown command specifier.
  ASSERT_EQ(m.send(frame(kSdoRx + 1, 4, {0x40, 0x41, 0x60, 0x00})), hal::CanResult::ok);
  ASSERT_EQ(m.send(frame(kSdoRx + 1, 8, {0xE0, 0x41, 0x60, 0, 0, 0, 0, 0})), hal::CanResult::ok);
  EXPECT_EQ(rig.bus.drive(0).counters().bad_dlc - bad_before, 2u);
  EXPECT_EQ(rig.bus.drive(0).target(), 0);
  EXPECT_EQ(rig.bus.drive(0).counters().sdo_aborts, 1u);  // the bad command is answered with an abort
}

}  // namespace
}  // namespace kerf::test
