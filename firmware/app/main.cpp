// The kerf command: fit, plan, weld, run, check, home, jog and touch-off; it links no simulator (the
// build checks its symbols). The simulator is kerf-sim (sim_main.cpp).
// Exit codes: 0 success, 1 the fit or the output failed, 2 bad options or
// bad input (the message is on stderr, stdout stays empty).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>

#include "app/check_command.hpp"
#include "app/fit_command.hpp"
#include "app/home_command.hpp"
#include "app/jog_command.hpp"
#include "app/plan_command.hpp"
#include "app/run_command.hpp"
#include "app/run_options.hpp"
#include "app/weld_command.hpp"
#include "machine/machine_factory.hpp"

#ifndef KERF_VERSION
#define KERF_VERSION "unknown"
#endif

int main(int argc, char** argv) {
  using namespace kerf::app;
  using kerf::io::kExitFailure;
  using kerf::io::kExitUsage;
  try {
    CLI::App app("kerf: fit circular arcs to the points of a cut path", "kerf");
    app.set_version_flag("--version", "kerf " KERF_VERSION);
    app.require_subcommand(1);
    // Only the command named first is built when it is one: building the
    // options of every command cost a small file's `kerf weld` a tenth of
    // its run. Anything else (--help, a typo) gets them all.
    static const char* const kCommands[] = {"fit", "plan", "sim", "run", "check", "home", "jog", "touch-off", "weld"};
    const char* only = nullptr;
    for (const char* name : kCommands)
      if (argc > 1 && std::strcmp(argv[1], name) == 0) only = name;
    const auto wanted = [only](const char* name) { return only == nullptr || std::strcmp(only, name) == 0; };
    kerf::job::FitOptions fit_opts;
    CLI::App* fit = wanted("fit") ? add_fit_command(app, fit_opts) : nullptr;
    PlanOptions plan_opts;
    CLI::App* plan = wanted("plan") ? add_plan_command(app, plan_opts) : nullptr;
    // `kerf sim` moved to kerf-sim: a hint, whatever follows.
    CLI::App* sim = nullptr;
    if (wanted("sim")) {
      sim = app.add_subcommand("sim", "Moved: the simulator is `kerf-sim sim` (package kerf-sim)");
      sim->prefix_command();
      sim->set_help_flag();
    }
    RunOptions run_opts;
    CLI::App* run = wanted("run") ? add_run_command(app, run_opts) : nullptr;
    CheckOptions check_opts;
    CLI::App* check = wanted("check") ? add_check_command(app, check_opts, true) : nullptr;
    HomeOptions home_opts;
    CLI::App* home = wanted("home") ? add_home_command(app, home_opts) : nullptr;
    JogOptions jog_opts;
    CLI::App* jog = wanted("jog") ? add_jog_command(app, jog_opts) : nullptr;
    TouchOffOptions touch_opts;
    CLI::App* touch = wanted("touch-off") ? add_touch_off_command(app, touch_opts) : nullptr;
    WeldCommandOptions weld_opts;
    CLI::App* weld = wanted("weld") ? add_weld_command(app, weld_opts) : nullptr;
    try {
      app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --version
      return app.exit(e);
    } catch (const CLI::ParseError& e) {
      std::fprintf(stderr, "kerf: %s\nRun with --help for more information.\n", e.what());
      return kExitUsage;
    }
    const auto parsed = [](const CLI::App* c) { return c != nullptr && c->parsed(); };
    if (parsed(fit)) return run_fit(fit_opts);
    if (parsed(plan)) return run_plan(plan_opts);
    if (parsed(weld)) return run_weld(weld_opts);
    if (parsed(run)) return run_run(run_opts);
    if (parsed(check)) return run_check(check_opts, "kerf", kerf::machine::check_lines);
    if (parsed(home)) return home_job(home_opts, "kerf", kerf::machine::check_lines, kerf::machine::open_lines);
    if (parsed(jog)) return jog_job(jog_opts, "kerf", kerf::machine::check_lines, kerf::machine::open_lines);
    if (parsed(touch))
      return touch_off_job(touch_opts, "kerf", kerf::machine::check_lines, kerf::machine::open_lines);
    if (parsed(sim)) {
      std::fprintf(stderr, "kerf: sim: the simulator is `kerf-sim sim` (package kerf-sim); kerf runs machines only\n");
      return kExitUsage;
    }
    return kExitUsage;  // require_subcommand(1) makes this unreachable
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "kerf: out of memory\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kerf: internal error: %s\n", e.what());
  }
  return kExitFailure;
}
