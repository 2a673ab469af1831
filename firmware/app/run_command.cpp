#include "app/run_command.hpp"

#include <cstdio>
#include <memory>
#include <string>

#include "app/job_input.hpp"
#include "control/fit_paths.hpp"
#include "control/program_job.hpp"
#include "control/run_report.hpp"
#include "control/streamed_job.hpp"
#include "control/soft_limits.hpp"
#include "io/input_file.hpp"
#include "io/options.hpp"
#include "job/machine_state.hpp"
#include "machine/homing.hpp"
#include "machine/machine_factory.hpp"
#include "machine/machine_run.hpp"

namespace kerf::app {

using io::kExitFailure;
using io::kExitUsage;

int run_job(const RunOptions& opts, const char* who, RunCheck check, LinesOpener open_lines) {
  std::string error;
  config::Config cfg;
  if (!io::input_readable(opts.config) || !io::input_readable(opts.job)) return kExitUsage;
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
  const std::string says = std::string(who) + ": run";
  // The job streams from its file (control/streamed_job.hpp): each path is
  // fitted, checked against the soft limits and the machine's lines, and held
  // off for a bench (no torch: every path a dry run, so no safety input is
  // ever stood in for in software) or --dry-run (the outputs too) as it is
  // read; a bad job that fits in the ring is refused here, before anything moves.
  // Where the machine stands is not known before the link is up, so the first
  // travel is checked from the first pierce point on.
  control::StreamedJob streamed;
  if (const int rc = open_streamed(cfg, opts.job, opts.dry_run, says.c_str(), streamed); rc != 0) return rc;
  if (!control::fully_limited(cfg.machine))
    std::fprintf(stderr, "%s: %s: machine.axis: x and y need min and max (soft limits): the job is not checked "
                         "against the table\n", says.c_str(), cfg.file.c_str());
  // Before anything moves: where the machine is must be known.
  job::MachineState state;
  if (!cfg.machine.state.empty() && !job::load_machine_state(cfg.machine.state, state, error)) {
    std::fprintf(stderr, "%s: run: machine.state: %s\n", who, error.c_str());
    return kExitUsage;
  }
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
  control::JobSource& source = streamed.source();
  if (!control::open_journal(opts.journal, opts.resume, source, journal, from)) return kExitUsage;
  // The report's facts of the job: complete once the stream has ended.
  const machine::JobFacts facts = [&](control::RunSummary& sum) {
    const control::StreamTotals t = streamed.totals();
    sum.paths = t.paths;
    sum.planned = t.segments;
    if (t.gcode) control::describe_program(t.summary, sum);
    sum.cut_rules = t.cut_rules;
    sum.forced_commits = t.forced_commits;
  };
  const int rc = machine::run_on_machine(source, facts, cfg, *link, *gpio, journal.get(), from, opts.resume,
                                         opts.report, opts.reset, opts.dry_run,
                                         opts.assume_homed ? "assumed (--assume-homed)" : "kerf home");
  // The offsets the program set are kept once it has run to its end (a
  // stopped run leaves the machine state as it was).
  const control::StreamTotals t = streamed.totals();
  if (t.gcode && rc == 0 && t.ended && !cfg.machine.state.empty() &&
      !job::save_machine_state(cfg.machine.state, t.summary.interp.state, error)) {
    std::fprintf(stderr, "%s: run: machine.state: %s\n", who, error.c_str());
    return kExitFailure;
  }
  return rc;
}

int run_run(const RunOptions& opts) { return run_job(opts, "kerf", machine::check_lines, machine::open_lines); }

}  // namespace kerf::app
