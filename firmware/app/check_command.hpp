// `kerf check JOB --config FILE` (and `kerf-sim check`): what a run of the job
// would do, without moving anything: the fitted segment and pierce counts,
// the time it will take (control/job_time.hpp: the board's planner under the
// machine's limits, with pierces, dwells and pauses), its extents against the
// soft limits, and every reason the run would be refused. Writes the plot
// with the table's outline (--plot). Exit 0: the job would run; 2: it would
// be refused (each reason on stderr, "FILE:LINE: reason"); 1: the
// configuration's safety rules refuse the machine itself.
#pragma once

#include <string>

#include "app/run_command.hpp"

namespace CLI {
class App;
}

namespace kerf::app {

struct CheckOptions {
  std::string config;
  std::string plot;
  std::string job;
};

CLI::App* add_check_command(CLI::App& app, CheckOptions& opts, bool config_required);

// kerf: kerf run's rules (strict interpreter, the machine's outputs, the
// safety lines: `check`; null for kerf-sim, which checks what `kerf-sim sim`
// runs, from [sim] start).
int run_check(const CheckOptions& opts, const char* who, RunCheck check);

}  // namespace kerf::app
