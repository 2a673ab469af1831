// `kerf plan`: fit the points of a file, then run the constant-feed
// interpolator over the fitted path (no hardware, no simulator), write the
// setpoint trace as CSV and print a summary.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace kerf::app {

// The options as given, still text, checked by run_plan so that every
// message has the "kerf: --option: ..." form.
struct PlanOptions {
  std::string tol;
  std::string criterion = "vertex";
  std::string numeric = "double";  // the fit's scalar type: double or fixed
  std::string feed;    // mm/min
  std::string period;  // s
  std::string accel;   // mm/s^2
  std::string jerk;    // mm/s^3; empty or 0: trapezoidal ramps, else S-curves
  std::string corner = "1";  // degrees
  std::string counts_per_mm;
  std::string trace;   // OUT.csv, or - for stdout
  std::string file;
};

// Adds the `plan` subcommand to app, storing into opts.
CLI::App* add_plan_command(CLI::App& app, PlanOptions& opts);

// Runs it; returns the exit code (see fit_command.hpp).
int run_plan(const PlanOptions& opts);

}  // namespace kerf::app
