// `kerf run`'s options, as given (checked by run_command.cpp).
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace kerf::cli {

struct RunOptions {
  std::string config;   // required
  std::string journal;
  bool resume = false;
  bool sim_gpio = false;  // bench mode: the torch and inputs simulated
  std::string report;
  std::string job;      // point file (paths separated by blank lines)
};

CLI::App* add_run_command(CLI::App& app, RunOptions& opts);

}  // namespace kerf::cli
