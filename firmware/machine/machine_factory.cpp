#include "machine/machine_factory.hpp"

#include <utility>

#include "control/machine_config.hpp"
#include "machine/can_link.hpp"
#if KERF_HAVE_MODBUS
#include "kerf/hal/modbus/modbus_link.hpp"
#endif
#if KERF_HAVE_GPIOD
#include "kerf/hal/gpio/gpiod_gpio.hpp"
#endif

namespace kerf::machine {

namespace {

#if KERF_HAVE_MODBUS
std::unique_ptr<hal::SegmentLink> open_modbus(const config::Config& cfg, std::string& error) {
  hal::ModbusConfig lc;
  lc.transport = cfg.link.kind == config::Link::Kind::modbus_rtu ? hal::ModbusConfig::Transport::rtu
                                                                 : hal::ModbusConfig::Transport::tcp;
  lc.host = cfg.link.host;
  lc.port = cfg.link.port;
  lc.device = cfg.link.device;
  lc.baud = cfg.link.baud;
  lc.unit = cfg.link.unit;
  // One attempt per call: the controller retries by cycling and keeps
  // watching its inputs meanwhile.
  lc.retries = 0;
  lc.response_timeout_s = cfg.link.timeout / 8.0 < 0.1 ? cfg.link.timeout / 8.0 : 0.1;
  return hal::ModbusSegmentLink::open(lc, error);
}
#endif

}  // namespace

bool check_lines(const config::Config& cfg, std::string& error) {
  const auto refuse = [&](const char* key, const std::string& why) {
    error = cfg.file + ": " + key + ": " + why;
    return false;
  };
  // Outputs that light or feed a torch: none on a bench.
  const std::pair<const char*, const hal::GpioLineConfig*> torch_outputs[] = {{"gpio.torch", &cfg.gpio.torch}};
  // The program's outputs that light the torch or feed it gas (M62-M65 on
  // outputs.torch, M7/M8 on outputs.mist/flood).
  const std::pair<const char*, int> program_outputs[] = {{"outputs.torch", cfg.program.torch_output},
                                                         {"outputs.mist", cfg.program.mist_output},
                                                         {"outputs.flood", cfg.program.flood_output}};
  if (cfg.bench.enabled) {
    for (const auto& [key, line] : torch_outputs)
      if (line->used) return refuse(key, "a bench ([bench] enabled = true) runs motion only: remove this output");
    for (const auto& [key, number] : program_outputs)
      if (number >= 0) return refuse(key, "a bench ([bench] enabled = true) runs motion only: remove this output");
    if (!cfg.gpio.outputs.empty())
      return refuse("gpio.output", "a bench ([bench] enabled = true) runs motion only: remove these outputs");
  } else {
    const std::pair<const char*, const hal::GpioLineConfig*> cut_lines[] = {{"gpio.torch", &cfg.gpio.torch},
                                                                            {"gpio.arc_ok", &cfg.gpio.arc_ok}};
    for (const auto& [key, line] : cut_lines)
      if (!line->used)
        return refuse(key, "kerf run needs this line (a bench without a torch: [bench] enabled = true)");
  }
  if (!cfg.gpio.estop.used) return refuse("gpio.estop", "kerf run needs an E-stop line, on a bench too");
  return true;
}

std::unique_ptr<hal::SegmentLink> open_link(const config::Config& cfg, std::string& error) {
  if (cfg.link.kind == config::Link::Kind::can) {
    CanLinkOptions o;
    read_can_link_options(cfg, o);
    o.iface = cfg.link.iface;
    return open_machine_can_link(o, error);
  }
#if KERF_HAVE_MODBUS
  return open_modbus(cfg, error);
#else
  error = "this build has no libmodbus (the target's libmodbus-dev was not found): use a CAN link";
  return nullptr;
#endif
}

std::unique_ptr<hal::Gpio> open_lines(const config::Config& cfg, std::string& error) {
#if KERF_HAVE_GPIOD
  return hal::open_gpiod(cfg.gpio, error);
#else
  (void)cfg;
  error = "gpio: this build has no libgpiod (the target's libgpiod-dev was not found)";
  return nullptr;
#endif
}

std::unique_ptr<control::Controller> make_controller(const control::Job& job, const control::ControllerConfig& ccfg,
                                                     hal::SegmentLink& link, hal::Gpio& gpio,
                                                     control::Journal* journal) {
  return std::make_unique<control::Controller>(job, ccfg, link, gpio, journal);
}

std::unique_ptr<control::Controller> make_controller(control::JobSource& job, const control::ControllerConfig& ccfg,
                                                     hal::SegmentLink& link, hal::Gpio& gpio,
                                                     control::Journal* journal) {
  return std::make_unique<control::Controller>(job, ccfg, link, gpio, journal);
}

std::unique_ptr<control::Controller> make_controller(const control::Job& job, const config::Config& cfg,
                                                     hal::SegmentLink& link, hal::Gpio& gpio,
                                                     control::Journal* journal) {
  return make_controller(job, control::controller_config(cfg), link, gpio, journal);
}

}  // namespace kerf::machine
