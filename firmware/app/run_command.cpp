#include "app/run_command.hpp"

#include <csignal>
#include <cstdio>
#include <cstring>
#include <memory>

#include "app/fit_command.hpp"
#include "job/fit_job.hpp"
#include "control/fit_paths.hpp"
#include "io/options.hpp"
#include "config/config.hpp"
#include "simulated/can_sim_link.hpp"
#include "control/controller.hpp"
#include "control/machine_config.hpp"
#include "io/output_file.hpp"
#include "simulated/sim_output.hpp"
#include "kerf/hal/modbus/modbus_link.hpp"
#include "kerf/hal/rt_loop.hpp"
#include "kerf/sim/scripted_gpio.hpp"
#if KERF_HAVE_GPIOD
#include "kerf/hal/gpio/gpiod_gpio.hpp"
#endif

namespace kerf::cli {

namespace {

volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_signal(int sig) { g_signal = sig; }

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
    control::CanSimOptions o = control::can_sim_options(cfg);
    o.iface = cfg.link.iface;
    return control::open_machine_can_link(o, error);
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
  if (opts.resume && opts.journal.empty()) return usage_error("--resume: needs --journal FILE");
  io::PointFile in;
  if (!read_job(opts.job, cfg.fit.criterion, in)) return kExitUsage;
  FittedJob fitted;
  if (const int rc = fit_paths_or_say(in, cfg.fit.criterion, cfg.fit.tol, cfg.cut.feed / 60.0, fitted,
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
  if (!open_journal(opts.journal, opts.resume, fitted.job, journal, from)) return kExitUsage;
  const hal::RtSetup rt = hal::rt_setup(cfg.rt.priority, cfg.rt.lock_memory);
  if (!rt.warning.empty()) std::fprintf(stderr, "kerf: run: %s\n", rt.warning.c_str());
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);

  control::Controller ctl(fitted.job, control::controller_config(cfg), *link, *gpio, journal.get());
  ctl.start(from);
  hal::RtLoop loop(cfg.machine.cycle);
  double t0 = -1.0, next_status = 1.0, now = 0.0;
  while (!ctl.finished()) {
    const double due = loop.wait_next();
    if (t0 < 0.0) t0 = due;
    if (g_signal != 0) ctl.request_stop(g_signal == SIGINT ? "stopped by SIGINT" : "stopped by SIGTERM");
    now = due - t0;
    ctl.cycle(now);
    if (now >= next_status) {  // the operator's status line, once a second
      next_status += 1.0;
      std::fprintf(stderr, "kerf: run: t %.0f s, %s, segment %lld of %zu; %s\n", now,
                   control::to_string(ctl.state()), static_cast<long long>(ctl.report().last_completed + 1),
                   ctl.report().planned, loop.stats().describe().c_str());
    }
  }
  const control::RunReport& r = ctl.report();
  io::SimSummary sum =
      io::summarise_run(r, fitted.job.paths.size(), config::to_string(cfg.link.kind), opts.resume, journal.get());
  sum.simulated = false;
  sum.torch_on = ctl.torch();
  sum.duration_s = now;  // on the loop's clock: overrun cycles are skipped, not counted
  sum.rt = loop.stats().describe();
  sum.rt_histogram = loop.stats().histogram();
  if (!opts.report.empty() && !io::write_output(opts.report, io::format_sim_json(sum))) {
    std::fprintf(stderr, "kerf: --report: cannot write %s: %s\n", opts.report.c_str(), std::strerror(errno));
    return kExitFailure;
  }
  std::fputs(io::format_sim_summary(sum).c_str(), stdout);
  std::fprintf(stdout, "kerf run: %s; wake-up lateness:\n%s", sum.rt.c_str(), sum.rt_histogram.c_str());
  if (r.state != control::State::done) {
    std::fprintf(stderr, "kerf: run: stopped after segment %lld: %s\n", static_cast<long long>(sum.last_executed),
                 r.reason.c_str());
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace kerf::cli
