#include "simulated/sim_machine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "control/soft_limits.hpp"
#include "kerf/hal/rt_loop.hpp"
#include "machine/machine_factory.hpp"
#include "simulated/sim_plant.hpp"

namespace kerf::simulated {

const char* to_string(BoardFaultKind k) {
  switch (k) {
    case BoardFaultKind::link_drop: return "link-drop";
    case BoardFaultKind::link_stall: return "link-stall";
    case BoardFaultKind::modbus_exception: return "modbus-exception";
    case BoardFaultKind::crc_error: return "crc-error";
    case BoardFaultKind::drive_fault: return "drive-fault";
    case BoardFaultKind::heartbeat_loss: return "heartbeat-loss";
    case BoardFaultKind::emcy: return "emcy";
    case BoardFaultKind::bus_off: return "bus-off";
    case BoardFaultKind::enable_refused: return "enable-refused";
    case BoardFaultKind::stall: return "stall";
  }
  return "unknown";
}


SimMachineConfig sim_machine_config(const config::Config& cfg) {
  SimMachineConfig m;
  m.rtu = cfg.link.kind == config::Link::Kind::modbus_rtu;
  m.motion.servo_period_s = cfg.machine.servo_period;
  m.motion.accel_mm_s2 = cfg.machine.accel;
  m.motion.vad = cfg.cut.rules.vad / 100.0;  // [cut] vad is in %
  m.motion.counts_per_mm = cfg.machine.axes.empty() ? 1000.0 : cfg.machine.axes.front().counts_per_mm;
  m.cycle_s = cfg.machine.cycle;
  m.z = config::z_limits(cfg.machine);
  m.soft_limits = control::soft_limits_of(cfg.machine);
  return m;
}

SimMachineResult run_sim_machine(const control::Job& job, const control::ControllerConfig& ccfg,
                                 const SimMachineConfig& mcfg, SimPlant& plant, hal::Gpio& gpio,
                                 control::Journal* journal, const control::ResumePoint& from) {
  control::WholeJobSource source(job);
  return run_sim_machine(source, ccfg, mcfg, plant, gpio, journal, from);
}

SimMachineResult run_sim_machine(control::JobSource& job, const control::ControllerConfig& ccfg,
                                 const SimMachineConfig& mcfg, SimPlant& plant, hal::Gpio& gpio,
                                 control::Journal* journal, const control::ResumePoint& from) {
  SimMachineResult res;
  using clock = std::chrono::steady_clock;
  const auto wall0 = clock::now();
  const double servo = plant.tick_s();
  const long ticks_per_cycle = std::max(1L, std::lround(mcfg.cycle_s / servo));
  hal::SegmentLink& link = plant.link();
  const std::unique_ptr<control::Controller> made = machine::make_controller(job, ccfg, link, gpio, journal);
  control::Controller& ctl = *made;
  ctl.start(from);
  std::vector<BoardFault> faults = mcfg.faults;
  std::stable_sort(faults.begin(), faults.end(),
                   [](const BoardFault& a, const BoardFault& b) { return a.at_s < b.at_s; });
  std::size_t next_fault = 0;
  const bool keep = !mcfg.trace_sink;  // else the sink takes each sample and nothing grows
  std::int64_t highest_done = -1;
  if (keep) res.trace.reserve(1 << 16);
  std::uint64_t ticks = 0;
  std::uint32_t last_executed = 0;
  std::int64_t running = -1;  // the job segment of the last sample
  // The last cycle's positions, to see that the axes have come to rest.
  std::vector<Vec2<double>> recent(static_cast<std::size_t>(ticks_per_cycle) + 1);
  auto sample = [&] {
    const hal::BoardStatus s = plant.truth();
    running = ctl.job_segment_of(s.executing);
    const sim::TraceSample t{static_cast<double>(ticks) * servo, s.position,
                             static_cast<std::uint32_t>(running < 0 ? 0 : running + 1), ctl.torch(), s.thc_lock, s.z};
    if (keep) res.trace.push_back(t);
    else mcfg.trace_sink(t);
    recent[ticks % recent.size()] = s.position;
    for (std::uint32_t q = last_executed + 1; q <= s.last_executed; ++q) {
      const std::int64_t done = ctl.job_segment_of(q);
      if (done < 0 || !ctl.completes_job_segment(q)) continue;
      if (mcfg.keep_executed) res.executed.push_back(done);
      ++res.executed_count;
      if (done <= highest_done) ++res.executed_repeats;
      highest_done = std::max(highest_done, done);
    }
    last_executed = std::max(last_executed, s.last_executed);
  };
  sample();
  // A few cycles after the controller is finished, so the trace shows the stop.
  int tail = 0;
  // Paced in real time (scaled by speed) on absolute deadlines, as `kerf run` is.
  hal::RtLoop pace(mcfg.speed > 0.0 ? mcfg.cycle_s / mcfg.speed : 1.0);
  auto last_wall = clock::now();
  auto last_progress = last_wall;
  std::uint64_t cycles = 0;
  while (tail < 3) {
    if (mcfg.progress && (++cycles & 255) == 0 && last_wall - last_progress > std::chrono::milliseconds(100)) {
      last_progress = last_wall;
      mcfg.progress({running, static_cast<double>(ticks) * servo,
                     std::chrono::duration<double>(last_wall - wall0).count()});
    }
    if (mcfg.speed > 0.0) pace.wait_next();
    const double now = static_cast<double>(ticks) * servo;
    while (next_fault < faults.size() && faults[next_fault].at_s <= now)
      if (!plant.inject(faults[next_fault++])) {
        res.setup_error = std::string("this link has no fault ") + to_string(faults[next_fault - 1].kind);
        return res;
      }
    // The journal's writer thread is not simulated: simulated time waits for it.
    while (ctl.journal_lagging()) std::this_thread::sleep_for(std::chrono::microseconds(100));
    ctl.cycle(now);
    if (mcfg.source_behind && mcfg.source_behind() && !ctl.finished()) {
      // The same cycle again once the producer has had a moment: no tick.
      std::this_thread::sleep_for(std::chrono::microseconds(50));
      last_wall = clock::now();
      continue;
    }
    // Link faults are wall-time events (timeouts, the board's watchdog): while
    // the link is down the simulation runs at least in real time, so that the
    // board moves on, blind, for as long as it would on a real machine.
    long ticks_now = ticks_per_cycle;
    const auto wall_now = clock::now();
    if (ctl.link_down()) {
      const double took = std::chrono::duration<double>(wall_now - last_wall).count();
      if (took < mcfg.cycle_s) std::this_thread::sleep_for(std::chrono::duration<double>(mcfg.cycle_s - took));
      ticks_now = std::max(ticks_per_cycle, std::lround(took / servo));
      last_wall = clock::now();
    } else {
      last_wall = wall_now;  // one clock read a cycle
    }
    for (long i = 0; i < ticks_now; ++i) {
      plant.tick();
      ++ticks;
      sample();
    }
    // Finished, and the axes at rest (the controller may have lost the link,
    // but the board brakes by itself and the simulation shows it).
    if (ctl.finished()) {
      const hal::BoardStatus s = plant.truth();
      const bool still = s.position == recent[(ticks - static_cast<std::uint64_t>(ticks_per_cycle)) % recent.size()];
      tail = still && s.state != hal::BoardState::running ? tail + 1 : 0;
    }
    if (now > mcfg.max_sim_s && (!mcfg.time_limit || now > mcfg.time_limit())) {
      res.setup_error = "the job did not finish within the simulation's time limit";
      break;
    }
  }
  if (mcfg.speed > 0.0) {
    res.rt = pace.stats().describe();
    res.rt_histogram = pace.stats().histogram();
  }
  res.run = ctl.report();
  res.board = plant.truth();
  res.run.stopped_at = res.board.position;  // where the axes really came to rest
  res.link_resends = link.resends();
  res.sim_s = static_cast<double>(ticks) * servo;
  res.wall_s = std::chrono::duration<double>(clock::now() - wall0).count();
  return res;
}

}  // namespace kerf::simulated
