// Linked into a kerf-like executable (kerf's own objects plus this file): a
// simulator object, the scripted GPIO, which the no-simulator check on kerf
// must find. Built, never run.
#include "kerf/sim/scripted_gpio.hpp"

kerf::sim::ScriptedGpio g_kerf_sim_probe{kerf::sim::ScriptedGpioOptions{}};
