#include "control/can_sim_machine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "kerf/hal/rt_loop.hpp"

namespace kerf::control {

CanMachineConfig can_machine_config(const config::Config& cfg) {
  CanMachineConfig m;
  m.can = can_sim_options(cfg);
  m.cycle_s = cfg.machine.cycle;
  return m;
}

SimMachineResult run_can_sim_machine(const Job& job, const ControllerConfig& ccfg, const CanMachineConfig& mcfg,
                                     hal::Gpio& gpio, Journal* journal, const ResumePoint& from) {
  SimMachineResult res;
  using clock = std::chrono::steady_clock;
  const auto wall0 = clock::now();
  const CanSimOptions& opts = mcfg.can;
  auto link = make_can_sim_link(opts, res.setup_error);
  if (!link) return res;
  const double sync = link->sync_period_s();
  const long ticks_per_cycle = std::max(1L, std::lround(mcfg.cycle_s / sync));

  Controller ctl(job, ccfg, *link, gpio, journal);
  ctl.start(from);
  std::vector<CanFault> faults = mcfg.faults;
  std::stable_sort(faults.begin(), faults.end(), [](const CanFault& a, const CanFault& b) { return a.at_s < b.at_s; });
  std::size_t next_fault = 0;
  res.trace.reserve(1 << 16);
  std::uint64_t ticks = 0;
  std::uint32_t last_executed = 0;
  auto sample = [&] {
    hal::BoardStatus s;
    link->status(s);
    const std::int64_t k = ctl.job_segment_of(s.executing);
    res.trace.push_back({static_cast<double>(ticks) * sync, s.position,
                         static_cast<std::uint32_t>(k < 0 ? 0 : k + 1), ctl.torch()});
    for (std::uint32_t q = last_executed + 1; q <= s.last_executed; ++q) {
      const std::int64_t done = ctl.job_segment_of(q);
      if (done >= 0) res.executed.push_back(done);
    }
    last_executed = std::max(last_executed, s.last_executed);
  };
  sample();
  int tail = 0;  // a few cycles after the controller is finished, so the trace shows the stop
  // Over SocketCAN each SYNC waits for the wall clock already.
  const bool paced = mcfg.speed > 0.0 && opts.iface.empty();
  hal::RtLoop pace(paced ? mcfg.cycle_s / mcfg.speed : 1.0);
  while (tail < 3) {
    if (paced) pace.wait_next();
    const double now = static_cast<double>(ticks) * sync;
    while (next_fault < faults.size() && faults[next_fault].at_s <= now) link->inject(faults[next_fault++].kind);
    ctl.cycle(now);
    for (long i = 0; i < ticks_per_cycle; ++i) {
      link->tick();
      ++ticks;
      sample();
    }
    if (ctl.finished()) {
      hal::BoardStatus s;
      link->status(s);
      const bool still = s.position == res.trace[res.trace.size() - 1 - static_cast<std::size_t>(ticks_per_cycle)].pos;
      tail = still && s.state != hal::BoardState::running ? tail + 1 : 0;
    }
    if (now > mcfg.max_sim_s) {
      res.setup_error = "the job did not finish within the simulation's time limit";
      break;
    }
  }
  if (paced) {
    res.rt = pace.stats().describe();
    res.rt_histogram = pace.stats().histogram();
  }
  res.run = ctl.report();
  link->status(res.board);
  // The controller names the fault bits; the link knows which drive and why.
  // Its text counts the link's sequence numbers; the report counts job segments.
  if (res.board.state == hal::BoardState::fault && res.run.state == State::fault && *link->last_error() != '\0') {
    std::string why = link->last_error();
    why = why.substr(0, why.find("; last completed segment"));
    res.run.reason += ": " + why + "; last completed job segment " +
                      (res.run.last_completed < 0 ? std::string("none") : std::to_string(res.run.last_completed));
  }
  res.run.stopped_at = res.board.position;  // where the axes really came to rest
  res.link_resends = 0;
  res.sim_s = static_cast<double>(ticks) * sync;
  res.wall_s = std::chrono::duration<double>(clock::now() - wall0).count();
  std::string log_error;
  if (!link->finish_log(log_error) && res.setup_error.empty()) res.setup_error = log_error;
  return res;
}

}  // namespace kerf::control
