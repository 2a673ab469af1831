// `kerf jog` and `kerf touch-off` (and kerf-sim's): short sessions over the
// configured link (machine/jog.hpp); the position and the work offsets go
// into the machine state file.
#pragma once

#include <string>

#include "app/run_command.hpp"

namespace CLI {
class App;
}

namespace kerf::app {

struct JogOptions {
  std::string config;
  std::string axis = "x";
  double distance = 0;  // incremental, mm
  double to = 0;        // absolute machine position, mm
  std::string continuous;  // "+" or "-": jog until released (stdin EOF or a line, SIGINT), up to the soft limit
  bool has_distance = false, has_to = false;
};

struct TouchOffOptions {
  std::string config;
};

CLI::App* add_jog_command(CLI::App& app, JogOptions& opts);
CLI::App* add_touch_off_command(CLI::App& app, TouchOffOptions& opts);

// Exit code: 0 done, 1 refused (not homed, E-stop) or stopped, 2 bad options or configuration.
int jog_job(JogOptions opts, const char* who, RunCheck check, LinesOpener open_lines);
int touch_off_job(const TouchOffOptions& opts, const char* who, RunCheck check, LinesOpener open_lines);

}  // namespace kerf::app
