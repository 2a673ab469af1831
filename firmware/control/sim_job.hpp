// One simulated job for `kerf sim`: start the simulated motion board (in
// this process, on an ephemeral 127.0.0.1 port or a fresh pty), connect the
// Modbus link to it, stream the segments, inject the scheduled faults at
// their simulated times, and collect what the board executed.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "control/segment_streamer.hpp"
#include "kerf/sim/motion_board.hpp"

namespace kerf::control {

enum class FaultKind : std::uint8_t { link_drop, link_stall, modbus_exception, crc_error };

struct ScheduledFault {
  FaultKind kind = FaultKind::link_drop;
  double at_s = 0.0;        // simulated time
  double duration_s = 0.5;  // wall time the link stays down (drop, stall)
};

struct SimJob {
  bool rtu = false;
  std::vector<hal::SegmentCommand> segments;
  Vec2<double> start{};         // where the board's axes are at power-up
  double speed = 0.0;           // simulated s per wall s; 0 = as fast as possible
  double servo_period_s = 0.001;
  double link_timeout_s = 1.0;  // the board's watchdog is half of it
  std::vector<ScheduledFault> faults;
};

struct SimJobResult {
  StreamReport stream;
  std::string setup_error;  // the board or the link could not be started
  std::vector<sim::TraceSample> trace;
  std::vector<std::uint32_t> executed;  // sequence numbers in execution order
  hal::BoardStatus board{};             // the board's own final status
  double sim_s = 0.0;
  double wall_s = 0.0;
};

SimJobResult run_sim_job(const SimJob& job, std::unique_ptr<sim::SegmentExecutor> executor);

const char* to_string(FaultKind k);

}  // namespace kerf::control
