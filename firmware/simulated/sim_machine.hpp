// The simulated machine for `kerf sim` and the scenario tests: the motion
// board (sim/) behind its Modbus server, the host's Modbus link, the GPIO
// lines (a hal::Gpio the caller provides, normally sim::ScriptedGpio) and
// the controller, run in lockstep on one simulated clock: each controller
// cycle is followed by the board's servo ticks for that cycle. Every run
// is therefore repeatable, at any --speed. Link health alone is judged on
// the wall clock (a stalled transaction takes wall time, whatever the
// simulation does), as it is on a real machine.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "control/controller.hpp"
#include "kerf/sim/motion_board.hpp"
#include "kerf/sim/motion_executor.hpp"

namespace kerf::simulated {
class SimPlant;
}

namespace kerf::simulated {

// Faults the board side can suffer; GPIO faults go through the Gpio script.
// The Modbus link's faults, a drive fault, and the CAN bus's and drives'
// (heartbeat_loss and on): each plant takes the ones it has.
enum class BoardFaultKind : std::uint8_t {
  link_drop, link_stall, modbus_exception, crc_error, drive_fault,
  heartbeat_loss, emcy, bus_off, enable_refused,
  stall  // the x axis jams: its actual position stops, the command runs on (either link)
};
const char* to_string(BoardFaultKind k);

struct BoardFault {
  BoardFaultKind kind = BoardFaultKind::link_drop;
  double at_s = 0.0;        // simulated time
  double duration_s = 0.5;  // wall time the link stays down (drop, stall)
};

// Where a run is, for a progress line: the job segment being run (0-based,
// -1 on a rapid or none), the simulated and the wall time so far.
struct SimProgress {
  std::int64_t segment = -1;
  double sim_s = 0.0;
  double wall_s = 0.0;
};

struct SimMachineConfig {
  bool rtu = false;
  sim::MotionConfig motion;     // servo period, accel, counts/mm
  double cycle_s = 0.002;       // controller period: a whole number of servo periods
  double speed = 0.0;           // simulated s per wall s; 0 = as fast as possible
  Vec2<double> start{};         // where the axes are at power-up
  motion::AxisLimits<double> z{};  // the z axis (config::z_limits); period 0: none
  motion::SoftLimits<double> soft_limits{};  // the board's own check (control::soft_limits_of)
  std::vector<BoardFault> faults;
  double max_sim_s = 600.0;     // give up (a stuck run, a hold never released) after this
  // When set, the limit past max_sim_s, read as the run goes (a streamed
  // job's grows as it is read: job_watch.hpp's TimeBudget).
  std::function<double()> time_limit;
  // Modbus TCP: the link hands its frames to the board's server in this
  // process (hal::ModbusFramePeer) instead of a loopback socket, unless a
  // fault needs the socket (link-drop, link-stall). False: always the socket.
  bool in_process = true;
  // Each trace sample as it is taken; when set, the result's trace stays
  // empty and memory does not grow with simulated time.
  std::function<void(const sim::TraceSample&)> trace_sink;
  // False: the result's executed list stays empty (its counts are kept), so
  // that memory does not grow with the job (kerf sim).
  bool keep_executed = true;
  // True when the job source had nothing ready for the controller since the
  // last call (a streamed job's producer behind: job_watch.hpp). The
  // producer is not simulated: simulated time waits for it, as for the
  // journal, so a run takes the same simulated time however fast it is read.
  std::function<bool()> source_behind;
  // Called about every 0.1 s of wall time (not at all when empty).
  std::function<void(const SimProgress&)> progress;
};

struct SimMachineResult {
  std::string setup_error;              // the board or the link could not be started
  control::RunReport run;
  // One sample per servo period (none with a trace_sink); `seq` is the job
  // segment + 1 being run (0 for a rapid or none), `torch` the torch output,
  // `thc_lock` the board's (gpio.thc_lock is it while the torch is on).
  std::vector<sim::TraceSample> trace;
  std::vector<std::int64_t> executed;   // job segments completed, in order (unless !keep_executed)
  std::uint64_t executed_count = 0;     // the same counted, kept or not
  std::uint64_t executed_repeats = 0;   // of them, a segment at or before one completed earlier
  hal::BoardStatus board{};             // the board's final status
  std::uint64_t link_resends = 0;
  double sim_s = 0.0;
  double wall_s = 0.0;
  std::string rt;            // the paced loop's statistics (--speed > 0), hal::RtStats::describe()
  std::string rt_histogram;  // and its histogram
};

// The board's motion settings and the controller period from a machine configuration.
SimMachineConfig sim_machine_config(const config::Config& cfg);

// On the Modbus board (TCP or RTU, as mcfg.rtu says).
SimMachineResult run_sim_machine(const control::Job& job, const control::ControllerConfig& ccfg,
                                 const SimMachineConfig& mcfg, hal::Gpio& gpio, control::Journal* journal,
                                 const control::ResumePoint& from);
// The same with the job as it streams (control/job_source.hpp).
SimMachineResult run_sim_machine(control::JobSource& job, const control::ControllerConfig& ccfg,
                                 const SimMachineConfig& mcfg, hal::Gpio& gpio, control::Journal* journal,
                                 const control::ResumePoint& from);
// On any plant (sim_plant.hpp); mcfg's motion and rtu settings are the plant's business then.
SimMachineResult run_sim_machine(const control::Job& job, const control::ControllerConfig& ccfg,
                                 const SimMachineConfig& mcfg, SimPlant& plant, hal::Gpio& gpio,
                                 control::Journal* journal, const control::ResumePoint& from);
// The same with the job as it streams (control/job_source.hpp).
SimMachineResult run_sim_machine(control::JobSource& job, const control::ControllerConfig& ccfg,
                                 const SimMachineConfig& mcfg, SimPlant& plant, hal::Gpio& gpio,
                                 control::Journal* journal, const control::ResumePoint& from);

}  // namespace kerf::simulated
