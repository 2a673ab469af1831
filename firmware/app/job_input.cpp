#include "app/job_input.hpp"

#include <cstdio>

#include "control/machine_config.hpp"
#include "control/program_job.hpp"
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

}  // namespace kerf::app
