// How long a job will take, before it runs (`kerf check`): each block the
// controller streams (the travel to a pierce point at the rapid feed, each
// path at its feeds) run through the board's own executor and interpolator
// (core/motion: the Modbus board's planner, trapezoidal ramps under
// machine.accel, the arcs' and joints' speed caps, z moves under the z axis's limits, its look-ahead), period by
// period; the controller's cycle quantises each hand-over. Between blocks:
// the pierce (arc-OK after arc_ok_s, then the pierce delay), dwells, pauses
// (operator_delay_s: the operator is not modelled further) and M66 waits at
// their timeout (inputs stay low, as in the simulator).
#pragma once

#include <cstddef>

#include "control/job.hpp"
#include "kerf/motion/axis_move.hpp"

namespace kerf::control {

struct JobTimeSettings {
  double servo_period_s = 0.001;
  double cycle_s = 0.002;          // the controller's loop period
  double accel_mm_s2 = 1000;
  double vad = 0.9;
  double counts_per_mm = 1000;
  std::size_t lookahead = 16;      // the board's interpolator queue (the simulated board's)
  std::size_t board_queue = 32;    // the board's segment queue (its credit)
  double rapid_feed_mm_s = 10000.0 / 60.0;
  double pierce_delay_s = 0.5;     // where a path does not carry its own
  double arc_ok_s = 0.05;          // torch on -> arc-OK (the simulated torch's)
  double operator_delay_s = 1.0;   // a pause (M0/M1) lasts this long
  Vec2<double> start{};            // where the machine stands before the first travel
  motion::AxisLimits<double> z{};  // the z axis (config::z_limits); none: no z moves
};

struct JobTime {
  double total_s = 0;
  double cut_s = 0, travel_s = 0, pierce_s = 0, actions_s = 0;
  std::size_t pierces = 0;
  bool ok = true;  // false: the planner refused a segment (the board would too)
};

JobTime estimate_job_time(const Job& job, const JobTimeSettings& settings);

}  // namespace kerf::control
