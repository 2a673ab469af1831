#include "app/run_command.hpp"

#include <cstdio>
#include <memory>
#include <string>

#include "config/config.hpp"
#include "control/fit_paths.hpp"
#include "control/machine_run.hpp"
#include "control/program_job.hpp"
#include "job/gcode_program.hpp"
#include "io/options.hpp"
#include "job/fit_job.hpp"
#include "kerf/hal/modbus/modbus_link.hpp"
#include "kerf/sim/scripted_gpio.hpp"
#include "simulated/can_sim_link.hpp"
#if KERF_HAVE_GPIOD
#include "kerf/hal/gpio/gpiod_gpio.hpp"
#endif

namespace kerf::app {

using io::kExitFailure;
using io::kExitUsage;

namespace {

std::unique_ptr<hal::Gpio> open_gpio(const config::Config& cfg, bool simulated, std::string& error) {
  if (simulated) {
    sim::ScriptedGpioOptions o;
    o.limit_count = cfg.gpio.limits.size();
    return std::make_unique<sim::ScriptedGpio>(o);
  }
  // A cut needs all three: the torch, its arc-OK and the E-stop.
  const std::pair<const char*, const hal::GpioLineConfig*> required[] = {
      {"gpio.torch", &cfg.gpio.torch}, {"gpio.arc_ok", &cfg.gpio.arc_ok}, {"gpio.estop", &cfg.gpio.estop}};
  for (const auto& [key, line] : required)
    if (!line->used) {
      error = cfg.file + ": " + key + ": kerf run needs this line (or --sim-gpio on a bench)";
      return nullptr;
    }
#if KERF_HAVE_GPIOD
  return hal::open_gpiod(cfg.gpio, error);
#else
  error = "gpio: this build has no libgpiod (the target's libgpiod-dev was not found); --sim-gpio runs a bench";
  return nullptr;
#endif
}

std::unique_ptr<hal::SegmentLink> open_link(const config::Config& cfg, std::string& error) {
  if (cfg.link.kind == config::Link::Kind::can) {
    simulated::CanSimOptions o = simulated::can_sim_options(cfg);
    o.iface = cfg.link.iface;
    return simulated::open_machine_can_link(o, error);
  }
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

}  // namespace

int run_run(const RunOptions& opts) {
  std::string error;
  config::Config cfg;
  if (!config::load(opts.config, cfg, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return kExitUsage;
  }
  if (opts.resume && opts.journal.empty()) return io::usage_error("--resume: needs --journal FILE");
  io::PointFile in;
  job::GcodeProgram prog;
  job::MachineState state;
  const bool gcode = job::is_gcode_path(opts.job);
  if (gcode) {
    if (!cfg.machine.state.empty() && !job::load_machine_state(cfg.machine.state, state, error)) {
      std::fprintf(stderr, "kerf: run: machine.state: %s\n", error.c_str());
      return kExitUsage;
    }
    if (!job::read_gcode_program(opts.job, config::interp_settings(cfg, true), state, prog, error) ||
        !control::machine_can_run(prog, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return kExitUsage;
    }
    for (const std::string& n : prog.interp.notes) std::fprintf(stderr, "kerf: run: %s\n", n.c_str());
  } else if (!job::read_job(opts.job, cfg.fit.criterion, in)) {
    return kExitUsage;
  }
  control::FittedJob fitted;
  if (const int rc = gcode ? control::fit_program_or_say(prog, cfg.fit.criterion, cfg.fit.tol, cfg.cut.feed / 60.0,
                                                         cfg.machine.max_feed / 60.0, fitted, cfg.fit.numeric)
                           : control::fit_paths_or_say(in, cfg.fit.criterion, cfg.fit.tol, cfg.cut.feed / 60.0, fitted,
                                                       cfg.fit.numeric);
      rc != 0)
    return rc;
  // The devices before the journal: a new journal replaces the old one, which
  // must not happen for a run that cannot even start.
  std::unique_ptr<hal::Gpio> gpio = open_gpio(cfg, opts.sim_gpio, error);
  if (!gpio) {
    std::fprintf(stderr, "kerf: run: %s\n", error.c_str());
    return kExitFailure;
  }
  std::unique_ptr<hal::SegmentLink> link = open_link(cfg, error);
  if (!link) {
    std::fprintf(stderr, "kerf: run: %s: %s\n", config::to_string(cfg.link.kind), error.c_str());
    return kExitFailure;
  }
  std::unique_ptr<control::Journal> journal;
  control::ResumePoint from;
  if (!control::open_journal(opts.journal, opts.resume, fitted.job, journal, from)) return kExitUsage;
  const int rc = control::run_on_machine(fitted.job, cfg, *link, *gpio, journal.get(), from, opts.resume, opts.report,
                                         gcode ? &prog : nullptr);
  // The offsets the program set are kept once it has run to its end (a
  // stopped run leaves the machine state as it was).
  if (gcode && rc == 0 && !cfg.machine.state.empty() &&
      !job::save_machine_state(cfg.machine.state, prog.interp.state, error)) {
    std::fprintf(stderr, "kerf: run: machine.state: %s\n", error.c_str());
    return kExitFailure;
  }
  return rc;
}

}  // namespace kerf::app
