#include "control/machine_config.hpp"

namespace kerf::control {

ControllerConfig controller_config(const config::Config& cfg) {
  ControllerConfig c;
  c.rapid_feed_mm_s = cfg.machine.rapid_feed / 60.0;
  c.pierce_delay_s = cfg.cut.pierce_delay;
  c.arc_ok_timeout_s = cfg.cut.arc_ok_timeout;
  c.link_timeout_s = cfg.link.timeout;
  // The board stops by itself after half the timeout without a request (its
  // watchdog); the controller switches the torch off then.
  c.link_watchdog_s = cfg.link.timeout / 2.0;
  c.wait_for_reset = cfg.gpio.reset.used;
  c.ferror.ferror_mm = cfg.machine.ferror;
  c.ferror.min_ferror_mm = cfg.machine.min_ferror;
  c.ferror.max_speed_mm_s = cfg.machine.max_feed / 60.0;
  return c;
}

MachineIo machine_io(const config::Config& cfg) {
  MachineIo io;
  for (const hal::GpioProgramLine& l : cfg.gpio.outputs) io.outputs.push_back(l.number);
  for (const hal::GpioProgramLine& l : cfg.gpio.inputs) io.inputs.push_back(l.number);
  io.analog_ignore = cfg.program.analog_ignore;
  io.bench = cfg.bench.enabled;
  return io;
}

}  // namespace kerf::control
