// `kerf home` (and `kerf-sim home`): a short session over the configured
// link that homes the axes (machine/homing.hpp) and keeps the result in the
// machine state file for a later `kerf run`.
#pragma once

#include <string>
#include <vector>

#include "app/run_command.hpp"

namespace CLI {
class App;
}

namespace kerf::app {

struct HomeOptions {
  std::string config;
  std::vector<std::string> axes;  // x y z; empty: x and y
};

CLI::App* add_home_command(CLI::App& app, HomeOptions& opts);

// Exit code: 0 every axis homed, 1 a fault (switch never tripped, E-stop,
// link), 2 bad options or configuration.
int home_job(const HomeOptions& opts, const char* who, RunCheck check, LinesOpener open_lines);

}  // namespace kerf::app
