// A whole job streamed through the link while the board's servo thread runs
// it, with every fault kind injected mid-stream. Either every segment runs
// exactly once and in order, or the streamer stops with a clear error, the
// board is in its safe state, and what ran is an in-order prefix.
#include <gtest/gtest.h>
#include <modbus/modbus.h>

#include <functional>
#include <string>

#include "control/segment_streamer.hpp"
#include "link_rig.hpp"

namespace kerf::test {
namespace {

using hal::BoardState;

constexpr std::uint32_t kSegments = 120;

struct JobRun {
  control::StreamReport rep;
  std::vector<std::uint32_t> executed;
};

JobRun stream_with_fault(LinkRig& rig, std::uint32_t at_seq, const std::function<void()>& inject,
                      double link_timeout_s = 2.0) {
  rig.board->start_servo(0.0);
  control::StreamConfig cfg;
  cfg.link_timeout_s = link_timeout_s;
  cfg.job_timeout_s = 30.0;
  const auto segs = job(kSegments);
  JobRun r;
  r.rep = control::stream_job(*rig.link, segs, cfg, [&](std::uint32_t seq) {
    if (seq == at_seq) inject();
  });
  rig.board->stop_servo();
  r.executed = rig.board->executed();
  return r;
}

void expect_completed_exactly_once(const JobRun& r) {
  EXPECT_TRUE(r.rep.ok) << r.rep.fault;
  EXPECT_EQ(r.rep.board.state, BoardState::done);
  EXPECT_EQ(r.rep.sent, kSegments);
  EXPECT_EQ(r.executed, one_to(kSegments));  // each once, in order
  EXPECT_FALSE(r.rep.board.torch);
}

class StreamingFaults : public ::testing::TestWithParam<Wire> {};

TEST_P(StreamingFaults, CleanJobRunsEverySegmentOnceInOrder) {
  RigOptions opt;
  opt.capacity = 8;  // far fewer slots than segments: credit must flow
  LinkRig rig(GetParam(), opt);
  const JobRun r = stream_with_fault(rig, 0, [] {});
  expect_completed_exactly_once(r);
  EXPECT_EQ(r.rep.resent, 0u);
  EXPECT_EQ(r.rep.board.duplicates, 0);
  EXPECT_DOUBLE_EQ(r.rep.board.position.x, kSegments);
}

TEST_P(StreamingFaults, ExceptionRepliesAreRetried) {
  LinkRig rig(GetParam());
  const JobRun r = stream_with_fault(rig, 30, [&] {
    rig.server->exception_replies(3, MODBUS_EXCEPTION_SLAVE_OR_SERVER_BUSY);
  });
  expect_completed_exactly_once(r);
  EXPECT_GE(r.rep.resent, 3u);
}

TEST_P(StreamingFaults, DelayedRepliesAreResentWithoutRunningTwice) {
  LinkRig rig(GetParam(), fast_timeouts());
  const JobRun r = stream_with_fault(rig, 40, [&] { rig.server->delay_replies(3, 0.12); });
  expect_completed_exactly_once(r);
  EXPECT_GE(r.rep.resent, 3u);
}

TEST_P(StreamingFaults, StallShorterThanTheLinkTimeoutIsRidden) {
  LinkRig rig(GetParam(), fast_timeouts());
  const JobRun r = stream_with_fault(rig, 50, [&] { rig.server->stall(0.3); });
  expect_completed_exactly_once(r);
  EXPECT_GE(r.rep.resent, 1u);
}

TEST_P(StreamingFaults, LinkDropShorterThanTheLinkTimeoutIsRidden) {
  LinkRig rig(GetParam(), fast_timeouts());
  const JobRun r = stream_with_fault(rig, 60, [&] { rig.server->drop_link(0.3); });
  expect_completed_exactly_once(r);
  EXPECT_GE(r.rep.resent, 1u);
  // TCP: the server closed the connection, so the link had to open a new one.
  if (GetParam() == Wire::tcp) {
    EXPECT_GE(rig.link->reconnects(), 1u);
  }
}

TEST_P(StreamingFaults, LinkDownTooLongStopsSafelyAndSaysWhatRan) {
  RigOptions opt = fast_timeouts();
  opt.watchdog_s = 0.2;  // the board stops on its own when the host goes silent
  LinkRig rig(GetParam(), opt);
  const JobRun r = stream_with_fault(rig, 70, [&] { rig.server->drop_link(5.0); }, 0.5);
  EXPECT_FALSE(r.rep.ok);
  EXPECT_NE(r.rep.fault.find("link down for more than 0.5 s"), std::string::npos) << r.rep.fault;
  EXPECT_LT(r.rep.sent, kSegments);
  // What ran is 1..last_executed, in order, nothing twice.
  const std::uint32_t last = r.rep.board.last_executed;
  EXPECT_GE(last, 1u);
  ASSERT_GE(r.executed.size(), last);
  EXPECT_EQ(std::vector<std::uint32_t>(r.executed.begin(), r.executed.begin() + last), one_to(last));
  EXPECT_EQ(r.executed, one_to(static_cast<std::uint32_t>(r.executed.size())));
  ASSERT_TRUE(rig.board->wait_until(
      [](const hal::BoardStatus& s) { return s.state == BoardState::fault; }, 5.0));
  const hal::BoardStatus s = rig.board->status();
  EXPECT_EQ(s.faults & hal::kFaultLinkWatchdog, hal::kFaultLinkWatchdog);
  EXPECT_FALSE(s.torch);
}

TEST(StreamingFaultsRtu, CorruptCrcIsResentWithoutRunningTwice) {
  LinkRig rig(Wire::rtu, fast_timeouts());
  const JobRun r = stream_with_fault(rig, 20, [&] { rig.server->corrupt_crc(3); });
  expect_completed_exactly_once(r);
  EXPECT_GE(r.rep.resent, 3u);
  EXPECT_GE(r.rep.board.duplicates, 1);
}

INSTANTIATE_TEST_SUITE_P(Wires, StreamingFaults, ::testing::Values(Wire::tcp, Wire::rtu), wire_name);

}  // namespace
}  // namespace kerf::test
