// The simulator's in-process Modbus TCP transport: the link hands its request
// frames to the board server (hal::ModbusFramePeer) and checks the replies as
// it does on a socket. The server builds each reply itself; here it also
// builds it with libmodbus (modbus_reply) and counts the replies that differ.
// And a whole simulated run gives the same trace and result over the socket
// and in process.
#include <gtest/gtest.h>

#include "kerf/hal/modbus/modbus_link.hpp"
#include "kerf/hal/modbus/register_map.hpp"
#include "kerf/sim/board_server.hpp"
#include "kerf/sim/motion_board.hpp"
#include "link_rig.hpp"
#include "simulated/sim_machine.hpp"
#include "../machine/fake_gpio.hpp"

namespace kerf::test {
namespace {

TEST(InProcess, RepliesAreLibmodbusBytesForEveryRequestTheLinkSends) {
  sim::BoardConfig bc;
  bc.capacity = 16;
  sim::MotionBoard board(bc, std::make_unique<sim::EndpointExecutor>());
  sim::ServerConfig sc;
  sc.in_process = true;
  sc.check_replies = true;
  std::string err;
  auto server = sim::BoardServer::start(board, sc, err);
  ASSERT_TRUE(server) << err;
  hal::ModbusConfig lc;
  lc.peer = server.get();
  lc.port = 1;  // never used: no socket
  lc.retries = 0;
  auto link = hal::ModbusSegmentLink::open(lc, err);
  ASSERT_TRUE(link) << err;

  hal::BoardStatus st;
  ASSERT_EQ(link->status(st), hal::LinkError::none) << link->last_error();  // FC03
  EXPECT_EQ(st.state, hal::BoardState::idle);
  const std::vector<hal::SegmentCommand> segs = job(12);
  std::uint32_t next = 0;
  for (int n = 1; next + static_cast<std::uint32_t>(n) <= 12 && n <= hal::modbus_map::kMaxSlotsPerWrite; ++n) {
    ASSERT_EQ(link->push_many(&segs[next], n, st), hal::LinkError::none) << link->last_error();  // FC23
    next += static_cast<std::uint32_t>(n);
    EXPECT_EQ(st.last_accepted, next);
  }
  // A gap in the sequence: the board's exception, decoded by the link.
  EXPECT_EQ(link->push(line_to(next + 2), st), hal::LinkError::rejected);
  EXPECT_EQ(link->command(hal::Command::start), hal::LinkError::none) << link->last_error();  // FC06
  EXPECT_EQ(link->command(static_cast<hal::Command>(99)), hal::LinkError::rejected);
  hal::HomeCommand h;  // FC16 at the home block, then command 7 (refused: running)
  EXPECT_NE(link->home(h, [] { return false; }), hal::LinkError::none);
  server->exception_replies(1, 6);  // busy
  EXPECT_EQ(link->status(st), hal::LinkError::busy);
  for (int i = 0; i < 50; ++i) board.tick();
  ASSERT_EQ(link->status(st), hal::LinkError::none);
  EXPECT_EQ(st.last_executed, next);
  EXPECT_GE(server->requests(), 12u);
  EXPECT_EQ(server->reply_mismatches(), 0u);
  EXPECT_EQ(board.executed(), one_to(next));
}

control::Job square_job() {
  control::Job job;
  control::CutPath p;
  p.start = {0, 0};
  for (const Vec2<double> end : {Vec2<double>{30, 0}, Vec2<double>{30, 30}, Vec2<double>{0, 30}, Vec2<double>{0, 0}}) {
    hal::SegmentCommand s;
    s.kind = SegmentKind::line;
    s.end = end;
    s.feed = 40.0;
    p.segments.push_back(s);
  }
  control::CutPath q = p;
  q.start = {40, 0};
  for (hal::SegmentCommand& s : q.segments) s.end.x += 40;
  job.paths = {p, q};
  return job;
}

TEST(InProcess, RunsTheSameAsTheSocket) {
  const control::Job job = square_job();
  control::ControllerConfig c;
  c.pierce_delay_s = 0.1;
  c.rapid_feed_mm_s = 200.0;
  simulated::SimMachineResult r[2];
  for (int k = 0; k < 2; ++k) {
    FakeGpio gpio;
    simulated::SimMachineConfig m;
    m.in_process = k == 1;
    r[k] = simulated::run_sim_machine(job, c, m, gpio, nullptr, {});
    ASSERT_EQ(r[k].setup_error, "");
    EXPECT_EQ(r[k].run.state, control::State::done) << r[k].run.reason;
  }
  ASSERT_EQ(r[0].trace.size(), r[1].trace.size());
  for (std::size_t i = 0; i < r[0].trace.size(); ++i) {
    EXPECT_EQ(r[0].trace[i].pos, r[1].trace[i].pos) << i;
    EXPECT_EQ(r[0].trace[i].seq, r[1].trace[i].seq) << i;
    EXPECT_EQ(r[0].trace[i].torch, r[1].trace[i].torch) << i;
  }
  EXPECT_EQ(r[0].executed, r[1].executed);
  EXPECT_EQ(r[1].executed.size(), 8u);
  EXPECT_EQ(r[0].link_resends, 0u);
  EXPECT_EQ(r[1].link_resends, 0u);
}

}  // namespace
}  // namespace kerf::test
