#include "app/sim_run_command.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "app/run_command.hpp"
#include "kerf/sim/scripted_gpio.hpp"
#include "simulated/can_sim_link.hpp"

namespace kerf::app {

namespace {

bool on_this_host(const config::Config& cfg, std::string& error) {
  const config::Link& l = cfg.link;
  const bool ok = l.kind == config::Link::Kind::modbus_tcp
                      ? l.host == "localhost" || l.host == "::1" || l.host.rfind("127.", 0) == 0
                  : l.kind == config::Link::Kind::modbus_rtu ? l.device.rfind("/dev/pts/", 0) == 0
                                                             : l.iface.rfind("vcan", 0) == 0;
  if (!ok)
    error = cfg.file + ": link: kerf-sim run drives only simulated boards and drives (Modbus TCP on a loopback "
                       "address, RTU on /dev/pts/N, CAN on vcanN); a machine runs under `kerf run`";
  return ok;
}

std::unique_ptr<hal::Gpio> scripted_lines(const config::Config& cfg, std::string&) {
  sim::ScriptedGpioOptions o;
  o.limit_count = cfg.gpio.limits.size();
  return std::make_unique<sim::ScriptedGpio>(o);
}

// Nothing leaves the process: the simulated drives on the in-process bus.
bool in_process(const config::Config&, std::string&) { return true; }

std::unique_ptr<hal::SegmentLink> in_process_drives(const config::Config& cfg, const HomeOptions& opts,
                                                    std::string& error) {
  simulated::CanSimOptions o = simulated::can_sim_options(cfg);
  if (opts.start.size() == 2) o.start = {opts.start[0], opts.start[1]};
  for (int a = 0; a < 3; ++a) {
    o.has_home_switch[a] = !std::isnan(opts.home_switch[a]);
    o.home_switch[a] = o.has_home_switch[a] ? opts.home_switch[a] : 0.0;
  }
  std::unique_ptr<simulated::CanSimLink> link = simulated::make_can_sim_link(o, error);
  if (link) {
    hal::BoardStatus st;
    link->status(st);
    std::printf("kerf-sim home: in-process CAN drives, powered up at %.3f %.3f\n", st.position.x, st.position.y);
  }
  return link;
}

}  // namespace

// The scripted operator stands at the machine: it gives the E-stop latch its
// start-up reset, as --reset does on a real one.
int run_sim_run(const RunOptions& opts) {
  RunOptions o = opts;
  o.reset = true;
  return run_job(o, "kerf-sim", on_this_host, scripted_lines);
}

int run_sim_home(const HomeOptions& opts) {
  if (opts.in_process) return home_job(opts, "kerf-sim", in_process, scripted_lines, in_process_drives);
  return home_job(opts, "kerf-sim", on_this_host, scripted_lines);
}
int run_sim_jog(const JogOptions& opts) { return jog_job(opts, "kerf-sim", on_this_host, scripted_lines); }
int run_sim_touch_off(const TouchOffOptions& opts) {
  return touch_off_job(opts, "kerf-sim", on_this_host, scripted_lines);
}

}  // namespace kerf::app
