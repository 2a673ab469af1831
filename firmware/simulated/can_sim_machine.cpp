#include "simulated/can_sim_machine.hpp"


#include "simulated/can_plant.hpp"

namespace kerf::simulated {

namespace {

BoardFaultKind can_fault_kind(CanFaultKind k) {
  switch (k) {
    case CanFaultKind::heartbeat_loss: return BoardFaultKind::heartbeat_loss;
    case CanFaultKind::emcy: return BoardFaultKind::emcy;
    case CanFaultKind::bus_off: return BoardFaultKind::bus_off;
    case CanFaultKind::enable_refused: return BoardFaultKind::enable_refused;
    case CanFaultKind::stall: return BoardFaultKind::stall;
  }
  return BoardFaultKind::emcy;
}

}  // namespace

CanMachineConfig can_machine_config(const config::Config& cfg) {
  CanMachineConfig m;
  m.can = can_sim_options(cfg);
  m.cycle_s = cfg.machine.cycle;
  return m;
}

SimMachineResult run_can_sim_machine(const control::Job& job, const control::ControllerConfig& ccfg,
                                     const CanMachineConfig& mcfg, hal::Gpio& gpio, control::Journal* journal,
                                     const control::ResumePoint& from) {
  control::WholeJobSource source(job);
  return run_can_sim_machine(source, ccfg, mcfg, gpio, journal, from);
}

SimMachineResult run_can_sim_machine(control::JobSource& job, const control::ControllerConfig& ccfg,
                                     const CanMachineConfig& mcfg, hal::Gpio& gpio, control::Journal* journal,
                                     const control::ResumePoint& from) {
  SimMachineResult res;
  std::unique_ptr<CanPlant> plant = make_can_plant(mcfg.can, res.setup_error);
  if (!plant) return res;
  SimMachineConfig m;
  m.cycle_s = mcfg.cycle_s;
  // Over SocketCAN each SYNC waits for the wall clock already.
  m.speed = mcfg.can.iface.empty() ? mcfg.speed : 0.0;
  m.max_sim_s = mcfg.max_sim_s;
  m.time_limit = mcfg.time_limit;
  m.keep_executed = mcfg.keep_executed;
  m.source_behind = mcfg.source_behind;
  m.trace_sink = mcfg.trace_sink;
  m.progress = mcfg.progress;
  for (const CanFault& f : mcfg.faults) m.faults.push_back({can_fault_kind(f.kind), f.at_s, 0.0});
  res = run_sim_machine(job, ccfg, m, *plant, gpio, journal, from);
  CanSimLink* link = &plant->can();
  // The controller names the fault bits; the link knows which drive and why.
  // Its text counts the link's sequence numbers; the report counts job segments.
  if (res.board.state == hal::BoardState::fault && res.run.state == control::State::fault &&
      *link->last_error() != '\0') {
    std::string why = link->last_error();
    why = why.substr(0, why.find("; last completed segment"));
    res.run.reason += ": " + why + "; last completed job segment " +
                      (res.run.last_completed < 0 ? std::string("none") : std::to_string(res.run.last_completed));
  }
  std::string log_error;
  if (!link->finish_log(log_error) && res.setup_error.empty()) res.setup_error = log_error;
  return res;
}

}  // namespace kerf::simulated
