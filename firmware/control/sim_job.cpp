#include "control/sim_job.hpp"

#include <modbus/modbus.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "kerf/hal/modbus/modbus_link.hpp"
#include "kerf/sim/board_server.hpp"

namespace kerf::control {

const char* to_string(FaultKind k) {
  switch (k) {
    case FaultKind::link_drop: return "link-drop";
    case FaultKind::link_stall: return "link-stall";
    case FaultKind::modbus_exception: return "modbus-exception";
    case FaultKind::crc_error: return "crc-error";
  }
  return "unknown";
}

namespace {

void inject(sim::BoardServer& server, const ScheduledFault& f) {
  switch (f.kind) {
    case FaultKind::link_drop: server.drop_link(f.duration_s); break;
    case FaultKind::link_stall: server.stall(f.duration_s); break;
    // Busy is transient: the link retries it (up to its retry count).
    case FaultKind::modbus_exception: server.exception_replies(3, MODBUS_EXCEPTION_SLAVE_OR_SERVER_BUSY); break;
    case FaultKind::crc_error: server.corrupt_crc(3); break;
  }
}

}  // namespace

SimJobResult run_sim_job(const SimJob& job, std::unique_ptr<sim::SegmentExecutor> exec) {
  SimJobResult res;
  const auto wall0 = std::chrono::steady_clock::now();
  sim::BoardConfig bc;
  bc.servo_period_s = job.servo_period_s;
  bc.start = job.start;
  if (!exec) {
    res.setup_error = "no motion executor";
    return res;
  }
  sim::MotionBoard board(bc, std::move(exec));
  sim::ServerConfig sc;
  sc.transport = job.rtu ? sim::ServerConfig::Transport::rtu : sim::ServerConfig::Transport::tcp;
  sc.watchdog_s = job.link_timeout_s / 2.0;
  auto server = sim::BoardServer::start(board, sc, res.setup_error);
  if (!server) return res;
  hal::ModbusConfig lc;
  lc.transport = job.rtu ? hal::ModbusConfig::Transport::rtu : hal::ModbusConfig::Transport::tcp;
  lc.port = server->port();
  lc.device = server->device();
  // Well above a loopback round trip even on a loaded machine, and short
  // against the link timeout so that several resends fit in it.
  lc.response_timeout_s = std::min(0.2, job.link_timeout_s / 4.0);
  auto link = hal::ModbusSegmentLink::open(lc, res.setup_error);
  if (!link) return res;

  board.start_servo(job.speed);
  std::thread faults([&] {  // each fault at its simulated time
    for (const ScheduledFault& f : job.faults)
      if (board.wait_sim_time(f.at_s)) inject(*server, f);
  });
  StreamConfig cfg;
  cfg.link_timeout_s = job.link_timeout_s;
  // In real time, poll at the servo rate instead of spinning on the link.
  cfg.poll_interval_s = job.speed > 0.0 ? job.servo_period_s / job.speed : 0.0;
  res.stream = stream_job(*link, job.segments, cfg);
  if (!res.stream.ok) {
    // The host gave up: wait for the board's watchdog to reach its safe state.
    board.wait_until([](const hal::BoardStatus& s) { return s.state != hal::BoardState::running; },
                     2.0 * job.link_timeout_s);
  }
  board.cancel_waits();
  faults.join();
  board.stop_servo();
  res.trace = board.trace();
  res.executed = board.executed();
  res.board = board.status();
  res.sim_s = board.sim_time();
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace kerf::control
