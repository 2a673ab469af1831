// `kerf run`: the controller on the real machine. The job is fitted path by
// path, the motion board is reached over Modbus (the config's link), the
// torch and the safety inputs over libgpiod, and the controller runs in a
// periodic loop on absolute deadlines (SCHED_FIFO and mlockall where
// permitted). SIGINT or SIGTERM stop it safely: torch off, motion stopped
// on the path, progress kept in the journal.
#pragma once

#include "app/run_options.hpp"

namespace kerf::app {

// Returns the exit code: 0 done, 1 stopped (fault, E-stop, signal) or a
// device failed, 2 bad options, config or job.
int run_run(const RunOptions& opts);

}  // namespace kerf::app
