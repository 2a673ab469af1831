// kerf-board-sim: the simulated motion board as a process of its own, for
// benches and end-to-end tests of `kerf run`: the Modbus server (TCP on
// 127.0.0.1, or RTU on a fresh pty) in front of the board running core/motion's
// interpolator in real time. Prints where it listens, then serves until
// SIGINT or SIGTERM.
//
//   kerf-board-sim [--port N] [--rtu] [--accel MM_S2] [--vad PERCENT] [--watchdog S]
//                  [--z-feed MM_MIN --z-accel MM_S2]  (a z axis: z moves run; default none)
//                  [--start X,Y] [--home-switch-x MM] [--home-switch-y MM]  (homing, command 7)
//                  [--home-switch-z MM]  (with --z-feed: z homes too)
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <vector>

#include "kerf/sim/board_server.hpp"
#include "kerf/sim/motion_executor.hpp"

int main(int argc, char** argv) {
  using namespace kerf;
  CLI::App app("kerf-board-sim: the simulated motion board over Modbus", "kerf-board-sim");
  int port = 0;
  bool rtu = false;
  double accel = 1500.0, watchdog = 0.5, vad = 90.0, z_feed = 0.0, z_accel = 500.0;
  app.add_option("--port", port, "TCP port on 127.0.0.1 (0: any free one)")->check(CLI::Range(0, 65535));
  app.add_flag("--rtu", rtu, "Modbus RTU on a new pseudo-terminal instead of TCP");
  app.add_option("--accel", accel, "Path acceleration, mm/s^2")->check(CLI::PositiveNumber);
  app.add_option("--vad", vad, "thc_lock while the speed is below this % of the cut feed (the machine's [cut] vad)")
      ->check(CLI::Range(0.0, 100.0));
  app.add_option("--watchdog", watchdog, "Stop safely when the host is silent this long (s); 0: never")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--z-feed", z_feed, "A z axis: its top feed, mm/min (0: no z axis, z moves are refused)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--z-accel", z_accel, "The z axis's acceleration, mm/s^2")->check(CLI::PositiveNumber);
  std::vector<double> x_limits, y_limits;  // the executor's soft limits, min max (mm)
  app.add_option("--x-limits", x_limits, "Soft limits of x: MIN MAX (mm); the board refuses a segment outside")
      ->expected(2);
  app.add_option("--y-limits", y_limits, "Soft limits of y: MIN MAX (mm)")->expected(2);
  std::vector<double> start = {0.0, 0.0};
  double switch_x = 0, switch_y = 0, switch_z = 0;
  app.add_option("--start", start, "Where the axes power up, mm (unhomed: the board's own frame)")
      ->delimiter(',')->expected(2);
  auto* sx = app.add_option("--home-switch-x", switch_x, "The x home switch, mm in the power-up frame (none: "
                                                         "homing x faults at the search distance)");
  auto* sy = app.add_option("--home-switch-y", switch_y, "The y home switch, mm in the power-up frame");
  auto* sz = app.add_option("--home-switch-z", switch_z, "The z home switch, mm (z powers up at 0; needs --z-feed)");
  CLI11_PARSE(app, argc, argv);

  // Block the stop signals before any thread starts, then wait for one.
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop, nullptr);

  std::string error;
  sim::MotionConfig mc;
  mc.accel_mm_s2 = accel;
  mc.vad = vad / 100.0;
  auto exec = sim::make_motion_executor(mc, error);
  if (!exec) {
    std::fprintf(stderr, "kerf-board-sim: %s\n", error.c_str());
    return 1;
  }
  sim::BoardConfig bc;
  bc.keep_trace = false;  // nobody reads it here: memory stays flat however long the board runs
  bc.start = {start[0], start[1]};
  bc.has_home_switch[0] = sx->count() > 0;
  bc.home_switch_at[0] = switch_x;
  bc.has_home_switch[1] = sy->count() > 0;
  bc.home_switch_at[1] = switch_y;
  bc.has_home_switch[2] = sz->count() > 0;
  bc.home_switch_at[2] = switch_z;
  if (bc.has_home_switch[2] && !(z_feed > 0)) {
    std::fprintf(stderr, "kerf-board-sim: --home-switch-z: the board has no z axis (give --z-feed)\n");
    return 2;
  }
  if (z_feed > 0) bc.z = {bc.servo_period_s, z_feed / 60.0, z_accel};
  const std::vector<double>* limits[2] = {&x_limits, &y_limits};
  for (int a = 0; a < 2; ++a) {
    if (limits[a]->empty()) continue;
    if (!((*limits[a])[0] < (*limits[a])[1])) {
      std::fprintf(stderr, "kerf-board-sim: --%c-limits: MIN must be below MAX\n", a == 0 ? 'x' : 'y');
      return 2;
    }
    bc.soft_limits.on[a] = true;
    bc.soft_limits.min[a] = (*limits[a])[0];
    bc.soft_limits.max[a] = (*limits[a])[1];
  }
  sim::MotionBoard board(bc, std::move(exec));
  sim::ServerConfig sc;
  sc.transport = rtu ? sim::ServerConfig::Transport::rtu : sim::ServerConfig::Transport::tcp;
  sc.port = port;
  sc.watchdog_s = watchdog;
  auto server = sim::BoardServer::start(board, sc, error);
  if (!server) {
    std::fprintf(stderr, "kerf-board-sim: %s\n", error.c_str());
    return 1;
  }
  board.start_servo(1.0);
  if (rtu)
    std::printf("kerf-board-sim: listening on %s\n", server->device().c_str());
  else
    std::printf("kerf-board-sim: listening on 127.0.0.1:%d\n", server->port());
  std::fflush(stdout);
  int sig = 0;
  sigwait(&stop, &sig);
  const hal::BoardStatus st = board.status();
  std::printf("kerf-board-sim: stopped by signal %d; last executed segment %u, %u duplicates dropped\n", sig,
              st.last_executed, st.duplicates);
  return 0;
}
