// The kerf-sim command: the simulator beside kerf. `sim` runs a job on the
// simulated machine in lockstep; `run` is kerf run's loop with scripted lines
// against the bench's simulated board or drives (sim_run_command.hpp). The
// board and the drives as processes of their own are kerf-board-sim and
// kerf-drive-sim (sim/). Exit codes as kerf's.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <new>

#include "app/check_command.hpp"
#include "app/home_command.hpp"
#include "app/jog_command.hpp"
#include "app/run_options.hpp"
#include "app/sim_options.hpp"
#include "app/sim_run_command.hpp"
#include "io/input_file.hpp"
#include "io/options.hpp"
#if KERF_HAVE_MODBUS
#include "simulated/sim_command.hpp"
#endif

#ifndef KERF_VERSION
#define KERF_VERSION "unknown"
#endif

int main(int argc, char** argv) {
  using namespace kerf::app;
  using kerf::io::kExitFailure;
  using kerf::io::kExitUsage;
  try {
    CLI::App app("kerf-sim: the kerf controller on simulated machines", "kerf-sim");
    app.set_version_flag("--version", "kerf-sim " KERF_VERSION);
    app.require_subcommand(1);
    kerf::simulated::SimOptions sim_opts;
    CLI::App* sim = add_sim_command(app, sim_opts);
    RunOptions run_opts;
    CLI::App* run = add_run_command(app, run_opts);
    run->description(
        "kerf run with scripted lines (E-stop released, arc-OK following the torch) against the bench's simulated "
        "board or drives: Modbus TCP on a loopback address, RTU on /dev/pts/N, CAN on vcanN");
    CheckOptions check_opts;
    CLI::App* check = add_check_command(app, check_opts, false);
    check->description("Check a job before `kerf-sim sim` runs it, moving nothing: segments, pierces, the time it "
                       "will take, its extents against the soft limits (travel from [sim] start), and what it would "
                       "refuse (exit 2 then)");
    HomeOptions home_opts;
    CLI::App* home = add_home_command(app, home_opts);
    home->description("kerf home with scripted lines against the bench's simulated board or drives "
                      "(kerf-board-sim --home-switch-x/-y/-z, kerf-drive-sim), or --in-process");
    home->add_flag("--in-process", home_opts.in_process,
                   "The config's CAN drives simulated on the in-process bus (virtual clock) instead of its link");
    home->add_option("--home-switch-x", home_opts.home_switch[0], "--in-process: the x switch, mm in the power-up "
                                                                  "frame (none: the search runs out)");
    home->add_option("--home-switch-y", home_opts.home_switch[1], "--in-process: the y switch, mm");
    home->add_option("--home-switch-z", home_opts.home_switch[2], "--in-process: the z switch, mm (z powers up at 0)");
    home->add_option("--start", home_opts.start, "--in-process: where the axes power up, mm")
        ->delimiter(',')
        ->expected(2);
    JogOptions jog_opts;
    add_jog_command(app, jog_opts)->description("kerf jog with scripted lines against the bench's simulated board");
    TouchOffOptions touch_opts;
    add_touch_off_command(app, touch_opts)
        ->description("kerf touch-off with scripted lines against the bench's simulated board");
    try {
      app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --version
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      std::fprintf(stderr, "kerf-sim: %s\nRun with --help for more information.\n", e.what());
      return kExitUsage;
    }
    if (run->parsed()) return run_sim_run(run_opts);
    if (check->parsed()) return run_check(check_opts, "kerf-sim", nullptr);
    if (home->parsed()) return run_sim_home(home_opts);
    if (app.got_subcommand("jog")) return run_sim_jog(jog_opts);
    if (app.got_subcommand("touch-off")) return run_sim_touch_off(touch_opts);
    if (sim->parsed() && !(kerf::io::input_readable(sim_opts.config) && kerf::io::input_readable(sim_opts.file)))
      return kExitUsage;
#if KERF_HAVE_MODBUS
    if (sim->parsed()) return kerf::simulated::run_sim(sim_opts);
#else
    if (sim->parsed()) {
      std::fprintf(stderr, "kerf-sim: sim: this build has no libmodbus (the target's libmodbus-dev was not found)\n");
      return kExitFailure;
    }
#endif
    return kExitUsage;  // require_subcommand(1) makes this unreachable
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "kerf-sim: out of memory\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kerf-sim: internal error: %s\n", e.what());
  }
  return kExitFailure;
}
