// Register map version 4's z moves: slot type 2 (centre_x carries the z end)
// and pos_z in status registers 20-21, encoded and decoded, a version-3
// status block refused, and a z move pushed over real libmodbus to a
// simulated board with a z axis.
#include <gtest/gtest.h>

#include "kerf/hal/modbus/register_map.hpp"
#include "link_rig.hpp"

namespace kerf::test {
namespace {

namespace map = hal::modbus_map;
using hal::BoardState;
using hal::LinkError;

hal::SegmentCommand z_move(std::uint32_t seq, Vec2<double> at, double z) {
  hal::SegmentCommand s;
  s.seq = seq;
  s.end = at;
  s.z_move = true;
  s.z = z;
  s.feed = 20.0;
  s.torch = true;
  return s;
}

TEST(RegisterMapZ, ZMoveSlotRoundTripsAndMalformedOnesAreRefused) {
  const hal::SegmentCommand a = z_move(9, {12.5, -3.25}, -1.234);
  std::uint16_t slot[map::kSlotRegs];
  ASSERT_TRUE(map::encode_slot(a, slot));
  EXPECT_EQ(slot[map::kSlotKind], map::kKindZMove);
  EXPECT_EQ(map::get_i32(slot + map::kSlotCentreX), -1234);
  EXPECT_EQ(map::get_i32(slot + map::kSlotCentreY), 0);
  EXPECT_EQ(slot[map::kSlotDir], 0);
  hal::SegmentCommand b;
  const char* why = nullptr;
  ASSERT_TRUE(map::decode_slot(slot, b, why)) << why;
  EXPECT_TRUE(b.z_move);
  EXPECT_DOUBLE_EQ(b.z, -1.234);
  EXPECT_DOUBLE_EQ(b.end.x, 12.5);
  EXPECT_DOUBLE_EQ(b.end.y, -3.25);
  EXPECT_DOUBLE_EQ(b.feed, 20.0);
  EXPECT_TRUE(b.torch);
  EXPECT_EQ(b.kind, SegmentKind::line);
  // An XY line decodes with z_move false.
  hal::SegmentCommand line = a;
  line.z_move = false;
  ASSERT_TRUE(map::encode_slot(line, slot));
  ASSERT_TRUE(map::decode_slot(slot, b, why));
  EXPECT_FALSE(b.z_move);
  // A z move with a direction or a centre_y, and type 3, are malformed.
  ASSERT_TRUE(map::encode_slot(a, slot));
  slot[map::kSlotDir] = 1;
  EXPECT_FALSE(map::decode_slot(slot, b, why));
  ASSERT_TRUE(map::encode_slot(a, slot));
  slot[map::kSlotCentreY + 1] = 7;
  EXPECT_FALSE(map::decode_slot(slot, b, why));
  EXPECT_STREQ(why, "z move with a direction or centre_y");
  slot[map::kSlotKind] = 3;
  EXPECT_FALSE(map::decode_slot(slot, b, why));
  EXPECT_STREQ(why, "unknown segment type");
}

TEST(RegisterMapZ, StatusCarriesPosZAndRefusesVersion3) {
  hal::BoardStatus st;
  st.state = BoardState::hold;
  st.position = {1.0, 2.0};
  st.z = -17.001;
  std::uint16_t r[map::kStatusRegs] = {};
  ASSERT_EQ(map::kStatusRegs, 24);  // 22..23: homing
  map::encode_status(st, r);
  EXPECT_EQ(r[map::kRegVersion], 4);
  EXPECT_EQ(map::get_i32(r + map::kRegPosZ), -17001);
  hal::BoardStatus back;
  ASSERT_TRUE(map::decode_status(r, back));
  EXPECT_DOUBLE_EQ(back.z, -17.001);
  EXPECT_EQ(back.state, BoardState::hold);
  // A version-3 board's block (20 registers, no pos_z) is refused.
  std::uint16_t v3[map::kStatusRegs] = {};
  map::encode_status(hal::BoardStatus{}, v3);
  v3[map::kRegVersion] = 3;
  v3[20] = v3[21] = 0;
  EXPECT_FALSE(map::decode_status(v3, back));
}

class ModbusZ : public ::testing::TestWithParam<Wire> {};

// Line, z move down, line, z move up: the board runs the z moves at rest and
// reports z; the status the host reads ends at the last z.
TEST_P(ModbusZ, ZMovesRunOverTheLinkAndPosZComesBack) {
  RigOptions opt;
  opt.z = {0.001, 50.0, 1000.0};
  LinkRig rig(GetParam(), opt);
  hal::BoardStatus st;
  ASSERT_EQ(rig.link->push(line_to(1), st), LinkError::none);
  ASSERT_EQ(rig.link->push(z_move(2, line_to(1).end, -2.5), st), LinkError::none);
  ASSERT_EQ(rig.link->push(line_to(3), st), LinkError::none);
  ASSERT_EQ(rig.link->push(z_move(4, line_to(3).end, 4.0), st), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
  for (int i = 0; i < 2000 && rig.board->status().state == BoardState::running; ++i) rig.board->tick();
  ASSERT_EQ(rig.link->status(st), LinkError::none);
  EXPECT_EQ(st.state, BoardState::done);
  EXPECT_EQ(st.last_executed, 4u);
  EXPECT_DOUBLE_EQ(st.z, 4.0);
  EXPECT_DOUBLE_EQ(st.position.x, 3.0);
  EXPECT_EQ(rig.board->executed(), (std::vector<std::uint32_t>{1, 2, 3, 4}));
  // z reached -2.5 between the lines.
  double lowest = 0;
  for (const sim::TraceSample& t : rig.board->trace()) lowest = std::min(lowest, t.z);
  EXPECT_DOUBLE_EQ(lowest, -2.5);
}

// A board without a z axis refuses a z move: bad-segment fault, z stays.
TEST_P(ModbusZ, ABoardWithoutZRefusesAZMove) {
  LinkRig rig(GetParam());
  hal::BoardStatus st;
  ASSERT_EQ(rig.link->push(z_move(1, {}, 3.0), st), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  for (int i = 0; i < 10; ++i) rig.board->tick();
  ASSERT_EQ(rig.link->status(st), LinkError::none);
  EXPECT_EQ(st.state, BoardState::fault);
  EXPECT_EQ(st.faults, hal::kFaultBadSegment);
  EXPECT_DOUBLE_EQ(st.z, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Wires, ModbusZ, ::testing::Values(Wire::tcp, Wire::rtu), wire_name);

}  // namespace
}  // namespace kerf::test
