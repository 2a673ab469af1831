// `kerf home` (and `kerf-sim home`): a short session over the configured
// link that homes the axes (machine/homing.hpp) and keeps the result in the
// machine state file for a later `kerf run`.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "app/run_command.hpp"
#include "kerf/hal/segment_link.hpp"

namespace CLI {
class App;
}

namespace kerf::app {

struct HomeOptions {
  std::string config;
  std::vector<std::string> axes;  // x y z; empty: every axis of the machine
  // kerf-sim only: the CAN link's simulated drives on the in-process bus
  // (virtual clock) rather than the configured link, with these switches
  // (mm in the power-up frame; NaN: none) and power-up position.
  bool in_process = false;
  double home_switch[3] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::quiet_NaN()};
  std::vector<double> start;  // x y, mm
};

// Opens the link the session drives (kerf: machine::open_link).
using LinkOpener = std::unique_ptr<hal::SegmentLink> (*)(const config::Config& cfg, const HomeOptions& opts,
                                                         std::string& error);

CLI::App* add_home_command(CLI::App& app, HomeOptions& opts);

// Exit code: 0 every axis homed, 1 a fault (switch never tripped, E-stop,
// link), 2 bad options or configuration.
int home_job(const HomeOptions& opts, const char* who, RunCheck check, LinesOpener open_lines,
             LinkOpener open_link = nullptr);

}  // namespace kerf::app
