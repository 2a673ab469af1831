// `kerf weld`: a G-code file in, the same job with its G1 polylines replaced
// by G2/G3 arcs out (see weld/weld.hpp for the rule).
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace kerf::app {

struct WeldCommandOptions {
  std::string tol;
  std::string criterion = "band";
  std::string decimals;
  bool no_split = false;
  std::string threads;
  std::string in;
  std::string out;
};

CLI::App* add_weld_command(CLI::App& app, WeldCommandOptions& opts);

// Returns the exit code: 0, 1 (the fit or the output failed), 2 (bad options or input).
int run_weld(const WeldCommandOptions& opts);

}  // namespace kerf::app
