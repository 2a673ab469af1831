#include "app/job_input.hpp"

#include <cstdio>

#include "control/machine_config.hpp"
#include "control/program_job.hpp"
#include "control/soft_limits.hpp"
#include "io/options.hpp"
#include "job/fit_job.hpp"
#include "job/machine_state.hpp"

namespace kerf::app {

int read_and_fit(const config::Config& cfg, const std::string& path, bool strict, const char* who, JobInput& out,
                 std::string* cannot_run) {
  std::string error;
  out.gcode = job::is_gcode_path(path);
  if (out.gcode) {
    job::MachineState state;
    if (!cfg.machine.state.empty() && !job::load_machine_state(cfg.machine.state, state, error)) {
      std::fprintf(stderr, "%s: machine.state: %s\n", who, error.c_str());
      return io::kExitUsage;
    }
    if (!job::read_gcode_program(path, config::interp_settings(cfg, strict), state, out.prog, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return io::kExitUsage;
    }
    if (strict && !control::machine_can_run(out.prog, control::machine_io(cfg), error)) {
      if (!cannot_run) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return io::kExitUsage;
      }
      *cannot_run = error;
    }
    for (const std::string& n : out.prog.interp.notes) std::fprintf(stderr, "%s: %s\n", who, n.c_str());
    return control::fit_program_or_say(out.prog, cfg.fit.criterion, cfg.fit.tol, cfg.cut.feed / 60.0,
                                       cfg.machine.max_feed / 60.0, out.fitted, cfg.fit.numeric, &cfg.cut.rules);
  }
  if (!job::read_job(path, cfg.fit.criterion, out.points)) return io::kExitUsage;
  return control::fit_paths_or_say(out.points, cfg.fit.criterion, cfg.fit.tol, cfg.cut.feed / 60.0, out.fitted,
                                   cfg.fit.numeric, &cfg.cut.rules);
}

int open_streamed(const config::Config& cfg, const std::string& path, bool dry_run, const char* who,
                  control::StreamedJob& out) {
  std::string error;
  control::StreamedJobSetup s;
  s.criterion = cfg.fit.criterion;
  s.numeric = cfg.fit.numeric;
  s.tol = cfg.fit.tol;
  s.feed_mm_s = cfg.cut.feed / 60.0;
  s.max_feed_mm_s = cfg.machine.max_feed / 60.0;
  s.rules = cfg.cut.rules;
  s.limits = control::soft_limits_of(cfg.machine);
  s.io = control::machine_io(cfg);
  s.torch_off = cfg.bench.enabled || dry_run;
  s.outputs_off = dry_run;
  if (job::is_gcode_path(path)) {
    if (!cfg.machine.state.empty() && !job::load_machine_state(cfg.machine.state, s.state, error)) {
      std::fprintf(stderr, "%s: machine.state: %s\n", who, error.c_str());
      return io::kExitUsage;
    }
    s.interp = config::interp_settings(cfg, true);
  }
  int rc = out.open(path, s, error);
  if (rc == 0) rc = out.prime(error);
  if (rc != 0) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return rc;
  }
  const control::StreamTotals t = out.totals();
  if (t.ended)
    for (const std::string& n : t.summary.interp.notes) std::fprintf(stderr, "%s: %s\n", who, n.c_str());
  return 0;
}

}  // namespace kerf::app
