// The simulated machine on CAN: the controller drives a CanSimLink (CiA 402
// drives on the in-process bus, or SocketCAN) instead of the Modbus board,
// in lockstep on one simulated clock: each controller cycle is followed by
// the SYNC periods it spans. Same result as run_sim_machine (trace, executed
// segments, the controller's report), so `kerf sim --link can` can report
// and trace as for Modbus. Faults: heartbeat-loss, emcy, bus-off,
// enable-refused at simulated times.
#pragma once

#include <functional>
#include <vector>

#include "simulated/can_sim_link.hpp"
#include "simulated/sim_machine.hpp"

namespace kerf::simulated {

struct CanFault {
  CanFaultKind kind = CanFaultKind::heartbeat_loss;
  double at_s = 0.0;  // simulated time
};

struct CanMachineConfig {
  CanSimOptions can;            // axes, node ids, SYNC period, iface, counts/mm, start
  double cycle_s = 0.002;       // controller period: a whole number of SYNC periods
  double speed = 0.0;           // simulated s per wall s; 0 = as fast as possible (in-process bus only)
  std::vector<CanFault> faults;
  double max_sim_s = 4 * 3600.0;
  std::function<double()> time_limit;  // as SimMachineConfig's
  bool keep_executed = true;           // as SimMachineConfig's
  std::function<bool()> source_behind; // as SimMachineConfig's
  std::function<void(const sim::TraceSample&)> trace_sink;  // as SimMachineConfig's
  std::function<void(const SimProgress&)> progress;
};

// The CAN settings and the controller period from a machine configuration.
CanMachineConfig can_machine_config(const config::Config& cfg);

SimMachineResult run_can_sim_machine(const control::Job& job, const control::ControllerConfig& ccfg,
                                     const CanMachineConfig& mcfg, hal::Gpio& gpio, control::Journal* journal,
                                     const control::ResumePoint& from);
// The same with the job as it streams (control/job_source.hpp).
SimMachineResult run_can_sim_machine(control::JobSource& job, const control::ControllerConfig& ccfg,
                                     const CanMachineConfig& mcfg, hal::Gpio& gpio, control::Journal* journal,
                                     const control::ResumePoint& from);

}  // namespace kerf::simulated
