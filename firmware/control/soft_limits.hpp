// A fitted job against the machine's soft limits ([[machine.axis]] min and
// max), before anything moves: every move the controller will command, in
// machine coordinates (work offsets are already applied by the interpreter):
// the travel to each pierce point (from `start`, when the caller knows where
// the machine stands), and each fitted segment with its arc's bulge, the cut
// rules' overcuts included. The executor checks each segment again on the
// board (core/motion/soft_limits.hpp).
#pragma once

#include <string>

#include "config/config.hpp"
#include "control/fit_paths.hpp"
#include "io/point_file.hpp"
#include "kerf/motion/soft_limits.hpp"

namespace kerf::control {

motion::SoftLimits<double> soft_limits_of(const config::Machine& m);
// Whether every axis of x and y has both min and max.
bool fully_limited(const config::Machine& m);

// The box every move of the job sweeps (travel from `start` when given).
motion::Extent<double> job_extent(const FittedJob& fitted, const Vec2<double>* start);

// False with "FILE:LINE: X 1.000 mm past max 1200.000 (path 2, segment 5)"
// for the first move outside the limits, FILE and LINE those of `source`
// (the point file or the G-code program's points the job was fitted from).
// first_path: the job number of fitted's first path (a streamed job checks
// each path alone, control/streamed_job.hpp).
bool check_soft_limits(const FittedJob& fitted, const io::PointFile& source, const motion::SoftLimits<double>& limits,
                       const Vec2<double>* start, std::string& error, std::size_t first_path = 0);

}  // namespace kerf::control
