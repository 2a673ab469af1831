// The two stages of `kerf plan`, kept apart from option handling: fitting the
// points into segments, and running the interpolator over them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "job/fit_job.hpp"
#include "kerf/geom/segment.hpp"
#include "kerf/motion/interpolator.hpp"

namespace kerf::job {

// Fits the points (tols: the file's per-point column, or empty) into
// segments with the named criterion (job/fit_job.hpp). On failure, returns
// false and sets error to a message without the "kerf: " prefix. numeric:
// the fit's scalar type.
bool fit_path(const std::vector<Vec2<double>>& pts, const std::vector<double>& tols, double tol,
              Criterion criterion, std::vector<Segment<double>>& out, std::string& error,
              Numeric numeric = Numeric::floating);

// What the run measured from its own setpoints.
struct PlanSummary {
  double length_mm = 0;        // the fitted path's length
  double time_s = 0;           // until the head is at rest at the end
  std::size_t setpoints = 0;
  double cruise_fraction = 0;  // of the periods, those at the programmed feed
  double max_accel_path = 0;   // mm/s^2, along the path (from s)
  double max_accel_plane = 0;  // mm/s^2, of the x-y velocity vector
  double max_jerk_path = 0;    // mm/s^3, along the path
};

// A run that would take more periods than this is refused: it would write
// gigabytes of trace (a period in ms given as s, say).
inline constexpr std::size_t kMaxSetpoints = 10000000;
// An S-curve averages over 2 accel / (jerk period) periods; beyond this the
// jerk is so small that the ramps would be longer than any cut.
inline constexpr std::size_t kMaxJerkWindow = 1000000;

// The length of the fitted path, mm.
double fitted_length(const std::vector<Segment<double>>& path);

// Runs the path at `feed` (mm/s) and appends one CSV row per setpoint to
// trace. The setpoint budget guards against a period far too small for the
// path; false with error set when the interpolator refuses a segment.
bool run_plan_path(const std::vector<Segment<double>>& path, double feed,
                   const motion::MotionConfig<double>& config, std::string& trace,
                   PlanSummary& summary, std::string& error);

// `kerf plan` once its options are checked (app/plan_command.cpp): the
// file's one path fitted, run at `feed`, the trace written, the summary
// printed (on stderr when the trace goes to stdout).
struct PlanRun {
  std::string file;  // a point or G-code file; "-": stdin
  Criterion criterion = Criterion::vertex;
  Numeric numeric = Numeric::floating;
  double tol = 0.0;
  double feed = 0.0;  // mm/min
  motion::MotionConfig<double> config;
  std::string trace;  // OUT.csv, or "-" for stdout
};

// Returns the exit code (io/options.hpp).
int plan_file(const PlanRun& run);

}  // namespace kerf::job
