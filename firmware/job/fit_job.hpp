// Fitting a job's points with a named criterion, for the commands that run
// the result (`kerf plan`, `kerf sim`): "vertex" (the minimal vertex fit) or
// "band" (the whole cut inside the band: --tol on both sides, or the point
// file's per-point tol column) or "biarc" (the fewest G1 biarcs inside the
// band of --tol, on estimated tangents; job/biarc_job.hpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/point_file.hpp"
#include "job/criterion.hpp"
#include "kerf/core/status.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::job {

// Which extra columns the caller reads: tangents (x y tx ty, or x y angle
// with `angles`) only `kerf fit --criterion biarc` does.
struct JobColumns {
  bool tangents = false;
  bool angles = false;
};

// Reads a job's point file ("-": stdin), or a G-code file (by its extension:
// .nc .ngc .gcode ...: the torch-on moves, split into paths at rapids and
// torch-off). When it cannot be used (unreadable,
// bad points, or a per-point tol or tangent column the criterion or command
// cannot use) prints "FILE:LINE: reason" on stderr and returns false.
bool read_job(const std::string& file, Criterion criterion, io::PointFile& out,
              const JobColumns& columns = {});

// Fits pts (tols: one per point, or empty) at tol, in the scalar type
// `numeric`. On failure returns false
// with `error` (no "kerf: " prefix) and `status` set. tie_break > 0 sets the
// double vertex and band fitters' tie-break precision (fit/fit.hpp; >= 1
// skips it); 0 keeps their own. `split`, if given, is set when the fit failed
// its own check and was fitted again in halves (then the pieces may be more
// than the fewest).
bool fit_job(const std::vector<Vec2<double>>& pts, const std::vector<double>& tols, double tol,
             Criterion criterion, std::vector<fit::Piece<double>>& out,
             std::string& error, Status& status, Numeric numeric = Numeric::floating,
             double tie_break = 0, bool* split = nullptr);

// How many times fit_job has fitted a path again as two halves because its
// fit failed its own check (its safety net; 0 on a sound fitter), since the
// program started. For the tests.
std::size_t fit_job_splits();

}  // namespace kerf::job
