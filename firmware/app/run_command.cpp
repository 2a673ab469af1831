#include "app/run_command.hpp"

#include <cstdio>
#include <memory>
#include <string>

#include "control/fit_paths.hpp"
#include "control/machine_config.hpp"
#include "control/program_job.hpp"
#include "job/gcode_program.hpp"
#include "io/options.hpp"
#include "job/fit_job.hpp"
#include "machine/homing.hpp"
#include "machine/machine_factory.hpp"
#include "machine/machine_run.hpp"

namespace kerf::app {

using io::kExitFailure;
using io::kExitUsage;

int run_job(const RunOptions& opts, const char* who, RunCheck check, LinesOpener open_lines) {
  std::string error;
  config::Config cfg;
  if (!config::load(opts.config, cfg, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return kExitUsage;
  }
  // The safety rules first: a refused configuration touches nothing.
  if (!check(cfg, error)) {
    std::fprintf(stderr, "%s: run: %s\n", who, error.c_str());
    return kExitFailure;
  }
  // The E-stop latch starts latched: something must be able to reset it.
  if (!opts.reset && !cfg.gpio.reset.used) {
    std::fprintf(stderr, "%s: run: the E-stop latch starts latched and nothing could reset it: "
                         "pass --reset or configure gpio.reset\n", who);
    return kExitFailure;
  }
  if (opts.resume && opts.journal.empty()) return io::usage_error("--resume: needs --journal FILE");
  io::PointFile in;
  job::GcodeProgram prog;
  job::MachineState state;
  const bool gcode = job::is_gcode_path(opts.job);
  if (!cfg.machine.state.empty() && !job::load_machine_state(cfg.machine.state, state, error)) {
    std::fprintf(stderr, "%s: run: machine.state: %s\n", who, error.c_str());
    return kExitUsage;
  }
  if (gcode) {
    if (!job::read_gcode_program(opts.job, config::interp_settings(cfg, true), state, prog, error) ||
        !control::machine_can_run(prog, control::machine_io(cfg), error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return kExitUsage;
    }
    for (const std::string& n : prog.interp.notes) std::fprintf(stderr, "%s: run: %s\n", who, n.c_str());
  } else if (!job::read_job(opts.job, cfg.fit.criterion, in)) {
    return kExitUsage;
  }
  control::FittedJob fitted;
  if (const int rc = gcode ? control::fit_program_or_say(prog, cfg.fit.criterion, cfg.fit.tol, cfg.cut.feed / 60.0,
                                                         cfg.machine.max_feed / 60.0, fitted, cfg.fit.numeric,
                                                         &cfg.cut.rules)
                           : control::fit_paths_or_say(in, cfg.fit.criterion, cfg.fit.tol, cfg.cut.feed / 60.0, fitted,
                                                       cfg.fit.numeric, &cfg.cut.rules);
      rc != 0)
    return rc;
  // A bench has no torch: every path runs as a dry run (no pierce, no wait
  // for arc-OK), so no safety input is ever stood in for in software.
  if (cfg.bench.enabled)
    for (control::CutPath& p : fitted.job.paths) p.torch = false;
  // Before anything moves: where the machine is must be known.
  if (!machine::check_homed(cfg, state, opts.assume_homed, error)) {
    std::fprintf(stderr, "%s: run: %s\n", who, error.c_str());
    return kExitFailure;
  }
  // The devices before the journal: a new journal replaces the old one, which
  // must not happen for a run that cannot even start.
  std::unique_ptr<hal::Gpio> gpio = open_lines(cfg, error);
  if (!gpio) {
    std::fprintf(stderr, "%s: run: %s\n", who, error.c_str());
    return kExitFailure;
  }
  std::unique_ptr<hal::SegmentLink> link = machine::open_link(cfg, error);
  if (!link) {
    std::fprintf(stderr, "%s: run: %s: %s\n", who, config::to_string(cfg.link.kind), error.c_str());
    return kExitFailure;
  }
  std::unique_ptr<control::Journal> journal;
  control::ResumePoint from;
  if (!control::open_journal(opts.journal, opts.resume, fitted.job, journal, from)) return kExitUsage;
  const int rc = machine::run_on_machine(fitted.job, cfg, *link, *gpio, journal.get(), from, opts.resume, opts.report,
                                         opts.reset, gcode ? &prog : nullptr, &fitted.cut_rules,
                                         opts.assume_homed ? "assumed (--assume-homed)" : "kerf home");
  // The offsets the program set are kept once it has run to its end (a
  // stopped run leaves the machine state as it was).
  if (gcode && rc == 0 && !cfg.machine.state.empty() &&
      !job::save_machine_state(cfg.machine.state, prog.interp.state, error)) {
    std::fprintf(stderr, "%s: run: machine.state: %s\n", who, error.c_str());
    return kExitFailure;
  }
  return rc;
}

int run_run(const RunOptions& opts) { return run_job(opts, "kerf", machine::check_lines, machine::open_lines); }

}  // namespace kerf::app
