// `kerf sim`: run a job on the simulated machine. The points are fitted path
// by path, then the controller runs them: rapids, pierces (torch on the
// simulated GPIO, arc-OK, pierce delay), cuts streamed over Modbus (TCP on
// 127.0.0.1 or RTU on a pty) to the simulated motion board, faults, the
// journal and resume, exactly as `kerf run` does on the real machine.
#pragma once

#include "simulated/sim_options.hpp"

namespace kerf::simulated {

// Returns the exit code: 0 done, 1 stopped by a fault or E-stop, 2 bad input.
int run_sim(const SimOptions& opts);

}  // namespace kerf::simulated
