// `kerf-sim run`: kerf run's loop and machine factory (the same link, the
// same controller) with the simulator's scripted lines in place of the
// machine's: E-stop never pressed, arc-OK following the torch. For the
// bench's own simulated board and drives only: the link must stay on this
// host (Modbus TCP to a loopback address, Modbus RTU on a pseudo-terminal,
// CAN on a vcan interface), so it can never move a real machine.
#pragma once

#include "app/run_options.hpp"
#include "app/home_command.hpp"
#include "app/jog_command.hpp"

namespace kerf::app {

int run_sim_run(const RunOptions& opts);
// `kerf-sim home`: kerf home with the scripted lines, on simulated boards and drives only.
int run_sim_home(const HomeOptions& opts);
int run_sim_jog(const JogOptions& opts);
int run_sim_touch_off(const TouchOffOptions& opts);

}  // namespace kerf::app
