// The register map over real libmodbus, TCP and RTU: queueing, credit,
// idempotent sequence numbers, commands, and replies that must be refused.
#include <gtest/gtest.h>
#include <modbus/modbus.h>

#include <cstring>

#include "kerf/hal/modbus/register_map.hpp"
#include "link_rig.hpp"

namespace kerf::test {
namespace {

using hal::BoardState;
using hal::LinkError;

class ModbusProtocol : public ::testing::TestWithParam<Wire> {};

TEST(RegisterMap, SlotRoundTripsAndRefusesBadValues) {
  hal::SegmentCommand a;
  a.seq = 0x12345678u;
  a.kind = SegmentKind::arc;
  a.end = {-1234.567, 89.001};
  a.centre = {-2000000.0, 0.5};
  a.dir = -1;
  a.feed = 25.5;
  a.torch = false;
  std::uint16_t slot[hal::modbus_map::kSlotRegs];
  ASSERT_TRUE(hal::modbus_map::encode_slot(a, slot));
  EXPECT_EQ(slot[0], 0x1234);  // high word first
  EXPECT_EQ(slot[1], 0x5678);
  hal::SegmentCommand b;
  const char* why = nullptr;
  ASSERT_TRUE(hal::modbus_map::decode_slot(slot, b, why));
  EXPECT_EQ(b.seq, a.seq);
  EXPECT_EQ(b.kind, SegmentKind::arc);
  EXPECT_EQ(b.dir, -1);
  EXPECT_DOUBLE_EQ(b.end.x, -1234.567);
  EXPECT_DOUBLE_EQ(b.centre.x, -2000000.0);
  EXPECT_DOUBLE_EQ(b.feed, 25.5);
  EXPECT_FALSE(b.torch);
  slot[hal::modbus_map::kSlotDir] = 0;  // an arc without a direction
  EXPECT_FALSE(hal::modbus_map::decode_slot(slot, b, why));
  EXPECT_STREQ(why, "arc direction not +1/-1");
  a.end.x = 3e6;  // 3 km does not fit 32-bit micrometres
  EXPECT_FALSE(hal::modbus_map::encode_slot(a, slot));
}

// Register 14 carries the torch (bit 0) and thc_lock (bit 1) independently;
// any other bit, or the previous map version, is refused.
TEST(RegisterMap, StatusRoundTripsTorchAndThcLock) {
  namespace map = hal::modbus_map;
  for (int bits = 0; bits < 4; ++bits) {
    hal::BoardStatus st;
    st.state = BoardState::running;
    st.credit = 5;
    st.executing = 70000;
    st.position = {12.345, -6.789};
    st.actual = {12.344, -6.788};
    st.torch = (bits & 1) != 0;
    st.thc_lock = (bits & 2) != 0;
    std::uint16_t r[map::kStatusRegs] = {};
    map::encode_status(st, r);
    EXPECT_EQ(r[map::kRegVersion], 4);
    EXPECT_EQ(r[map::kRegTorch], bits);
    hal::BoardStatus back;
    back.torch = !st.torch;
    back.thc_lock = !st.thc_lock;
    ASSERT_TRUE(map::decode_status(r, back));
    EXPECT_EQ(back.torch, st.torch);
    EXPECT_EQ(back.thc_lock, st.thc_lock);
    EXPECT_EQ(back.executing, 70000u);
    EXPECT_DOUBLE_EQ(back.position.x, 12.345);
  }
  hal::BoardStatus st;
  std::uint16_t r[map::kStatusRegs] = {};
  map::encode_status(st, r);
  r[map::kRegTorch] = 4;  // a bit this map does not define
  EXPECT_FALSE(map::decode_status(r, st));
  map::encode_status(st, r);
  r[map::kRegVersion] = 3;  // the map before z moves
  EXPECT_FALSE(map::decode_status(r, st));
}

// Found by fuzzing (tests/fuzz/corpus/modbus/int32_min_end_y): a slot whose
// coordinate is -2^31 um decoded, but the host's encoder refused the very
// segment (its range stopped at -2^31 + 1). Every decoded slot encodes back.
TEST(RegisterMap, SlotAtTheInt32LimitsRoundTrips) {
  std::uint16_t slot[hal::modbus_map::kSlotRegs] = {0x0027, 0x0000, 0, 0, 0, 64, 0x8000, 0x0000,
                                                    0x7FFF, 0xFFFF, 0, 0, 0, 1, 0, 0};
  hal::SegmentCommand s;
  const char* why = nullptr;
  ASSERT_TRUE(hal::modbus_map::decode_slot(slot, s, why)) << why;
  EXPECT_DOUBLE_EQ(s.end.y, -2147483.648);
  EXPECT_DOUBLE_EQ(s.centre.x, 2147483.647);
  std::uint16_t again[hal::modbus_map::kSlotRegs] = {};
  ASSERT_TRUE(hal::modbus_map::encode_slot(s, again));
  EXPECT_EQ(0, std::memcmp(slot, again, sizeof slot));
  s.end.y = -2147483.649;  // one micrometre beyond
  EXPECT_FALSE(hal::modbus_map::encode_slot(s, again));
}

TEST_P(ModbusProtocol, PushQueuesAndReturnsCredit) {
  LinkRig rig(GetParam());
  hal::BoardStatus st;
  for (std::uint32_t k = 1; k <= 3; ++k) ASSERT_EQ(rig.link->push(line_to(k), st), LinkError::none);
  EXPECT_EQ(st.last_accepted, 3u);
  EXPECT_EQ(st.credit, 16 - 3);
  EXPECT_EQ(st.state, BoardState::idle);
  hal::BoardStatus polled;
  ASSERT_EQ(rig.link->status(polled), LinkError::none);
  EXPECT_EQ(polled.credit, 13);
}

TEST_P(ModbusProtocol, ResentSequenceNumberIsDroppedNotRunTwice) {
  LinkRig rig(GetParam());
  hal::BoardStatus st;
  ASSERT_EQ(rig.link->push(line_to(1), st), LinkError::none);
  ASSERT_EQ(rig.link->push(line_to(1), st), LinkError::none);  // as after a lost reply
  ASSERT_EQ(rig.link->push(line_to(2), st), LinkError::none);
  EXPECT_EQ(st.duplicates, 1);
  EXPECT_EQ(st.credit, 16 - 2);
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::finish), LinkError::none);
  for (int i = 0; i < 5; ++i) rig.board->tick();
  EXPECT_EQ(rig.board->executed(), one_to(2));
  ASSERT_EQ(rig.link->status(st), LinkError::none);
  EXPECT_EQ(st.state, BoardState::done);
  EXPECT_EQ(st.last_executed, 2u);
  EXPECT_DOUBLE_EQ(st.position.x, 2.0);
  EXPECT_DOUBLE_EQ(st.position.y, 1.0);
}

TEST_P(ModbusProtocol, WriteOfSevenSlotsQueuesThemInOrder) {
  LinkRig rig(GetParam());
  const auto segs = job(7);
  hal::BoardStatus st;
  ASSERT_EQ(rig.link->push_many(segs.data(), 7, st), LinkError::none);
  EXPECT_EQ(st.last_accepted, 7u);
  EXPECT_EQ(st.credit, 16 - 7);
}

TEST_P(ModbusProtocol, SequenceGapAndFullQueueAreRejected) {
  RigOptions opt;
  opt.capacity = 2;
  LinkRig rig(GetParam(), opt);
  hal::BoardStatus st;
  EXPECT_EQ(rig.link->push(line_to(2), st), LinkError::rejected);  // 1 is missing
  EXPECT_NE(std::strstr(rig.link->last_error(), "push: rejected"), nullptr) << rig.link->last_error();
  ASSERT_EQ(rig.link->push(line_to(1), st), LinkError::none);
  ASSERT_EQ(rig.link->push(line_to(2), st), LinkError::none);
  EXPECT_EQ(st.credit, 0);
  EXPECT_EQ(rig.link->push(line_to(3), st), LinkError::rejected);
  EXPECT_EQ(rig.board->status().last_accepted, 2u);
}

TEST_P(ModbusProtocol, CommandsDriveTheStateMachine) {
  LinkRig rig(GetParam());
  hal::BoardStatus st;
  EXPECT_EQ(rig.link->command(hal::Command::resume), LinkError::rejected);  // not on hold
  ASSERT_EQ(rig.link->push(line_to(1), st), LinkError::none);
  ASSERT_EQ(rig.link->push(line_to(2), st), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::start), LinkError::none);
  ASSERT_EQ(rig.link->command(hal::Command::hold), LinkError::none);
  rig.board->tick();
  EXPECT_TRUE(rig.board->executed().empty());  // held: nothing runs
  ASSERT_EQ(rig.link->command(hal::Command::resume), LinkError::none);
  rig.board->tick();
  EXPECT_EQ(rig.board->executed(), one_to(1));
  ASSERT_EQ(rig.link->command(hal::Command::abort), LinkError::none);
  ASSERT_EQ(rig.link->status(st), LinkError::none);
  EXPECT_EQ(st.state, BoardState::fault);
  EXPECT_EQ(st.faults, hal::kFaultAbort);
  EXPECT_FALSE(st.torch);
  EXPECT_EQ(st.credit, 16);  // the queue was dropped
  ASSERT_EQ(rig.link->command(hal::Command::fault_reset), LinkError::none);
  ASSERT_EQ(rig.link->status(st), LinkError::none);
  EXPECT_EQ(st.state, BoardState::idle);
  EXPECT_EQ(st.faults, 0);
}

TEST_P(ModbusProtocol, WrongUnitIdReplyIsRefused) {
  LinkRig rig(GetParam(), fast_timeouts());
  rig.server->wrong_unit(100);
  hal::BoardStatus st;
  const LinkError e = rig.link->status(st);
  EXPECT_NE(e, LinkError::none);
  EXPECT_NE(std::strstr(rig.link->last_error(), "status:"), nullptr);
  rig.server->wrong_unit(0);
  EXPECT_EQ(rig.link->status(st), LinkError::none);  // the link recovers afterwards
}

TEST_P(ModbusProtocol, ShortReplyIsRefused) {
  LinkRig rig(GetParam(), fast_timeouts());
  rig.server->short_replies(100);
  hal::BoardStatus st;
  EXPECT_NE(rig.link->status(st), LinkError::none);
  EXPECT_NE(std::strstr(rig.link->last_error(), "status:"), nullptr) << rig.link->last_error();
  rig.server->short_replies(0);
  EXPECT_EQ(rig.link->status(st), LinkError::none);
}

TEST_P(ModbusProtocol, FinalExceptionIsReportedNotRetried) {
  LinkRig rig(GetParam());
  rig.server->exception_replies(1, MODBUS_EXCEPTION_SLAVE_OR_SERVER_FAILURE);
  hal::BoardStatus st;
  EXPECT_EQ(rig.link->push(line_to(1), st), LinkError::exception);
  EXPECT_NE(std::strstr(rig.link->last_error(), "Modbus exception"), nullptr) << rig.link->last_error();
  EXPECT_EQ(rig.link->resends(), 0u);
  EXPECT_EQ(rig.board->status().last_accepted, 0u);  // the board did nothing with it
}

TEST_P(ModbusProtocol, BusyExceptionIsRetried) {
  LinkRig rig(GetParam());
  rig.server->exception_replies(2, MODBUS_EXCEPTION_SLAVE_OR_SERVER_BUSY);
  hal::BoardStatus st;
  EXPECT_EQ(rig.link->push(line_to(1), st), LinkError::none);
  EXPECT_EQ(rig.link->resends(), 2u);
  EXPECT_EQ(st.last_accepted, 1u);
}

TEST_P(ModbusProtocol, LateReplyIsFlushedAndTheResendIsDropped) {
  LinkRig rig(GetParam(), fast_timeouts());
  rig.server->delay_replies(1, 0.15);  // three response timeouts
  hal::BoardStatus st;
  ASSERT_EQ(rig.link->push(line_to(1), st), LinkError::none) << rig.link->last_error();
  EXPECT_GE(rig.link->resends(), 1u);
  ASSERT_EQ(rig.link->push(line_to(2), st), LinkError::none) << rig.link->last_error();
  EXPECT_EQ(st.last_accepted, 2u);
  EXPECT_GE(st.duplicates, 1);  // the delayed write landed; its resend was dropped
  EXPECT_EQ(st.credit, 16 - 2);
}

TEST(ModbusRtu, CorruptCrcIsRefusedThenResent) {
  RigOptions opt;
  opt.response_timeout_s = 0.2;
  LinkRig rig(Wire::rtu, opt);
  rig.server->corrupt_crc(1);
  hal::BoardStatus st;
  ASSERT_EQ(rig.link->push(line_to(1), st), LinkError::none) << rig.link->last_error();
  EXPECT_EQ(rig.link->resends(), 1u);
  EXPECT_EQ(st.duplicates, 1);  // the first write was applied; only its reply was broken
  EXPECT_EQ(st.last_accepted, 1u);
  rig.server->corrupt_crc(100);
  EXPECT_EQ(rig.link->status(st), LinkError::malformed);
  EXPECT_NE(std::strstr(rig.link->last_error(), "CRC"), nullptr) << rig.link->last_error();
}

INSTANTIATE_TEST_SUITE_P(Wires, ModbusProtocol, ::testing::Values(Wire::tcp, Wire::rtu), wire_name);

}  // namespace
}  // namespace kerf::test
