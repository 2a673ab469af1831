// The controller's and the simulated machine's settings from a machine
// configuration: one place, so `kerf sim`, `kerf run` and the scenario tests
// read the config the same way.
#pragma once

#include "config/config.hpp"
#include "control/controller.hpp"

namespace kerf::control {

ControllerConfig controller_config(const config::Config& cfg);

}  // namespace kerf::control
