// `kerf sim`'s command line (app/sim_options.cpp); the options themselves
// are simulated/sim_options.hpp's, run by run_sim (simulated/sim_command.hpp).
#pragma once

#include "simulated/sim_options.hpp"

namespace CLI {
class App;
}

namespace kerf::app {

CLI::App* add_sim_command(CLI::App& app, simulated::SimOptions& opts);

}  // namespace kerf::app
