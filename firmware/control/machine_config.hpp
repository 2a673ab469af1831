// The controller's and the simulated machine's settings from a machine
// configuration: one place, so `kerf sim`, `kerf run` and the scenario tests
// read the config the same way.
#pragma once

#include "config/config.hpp"
#include "control/controller.hpp"
#include "control/program_job.hpp"

namespace kerf::control {

ControllerConfig controller_config(const config::Config& cfg);

// The program lines kerf run's machine has (program_job.hpp's check at load).
MachineIo machine_io(const config::Config& cfg);

}  // namespace kerf::control
