// Fitting a job's points with a named criterion, for the commands that run
// the result (`kerf plan`, `kerf sim`): "vertex" (the minimal vertex fit) or
// "band" (the whole cut inside the band: --tol on both sides, or the point
// file's per-point tol column).
#pragma once

#include <string>
#include <vector>

#include "io/point_file.hpp"
#include "kerf/core/status.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::cli {

// The criteria fit_job knows. Checked before the input is read.
bool criterion_supported(const std::string& criterion);

// Reads a job's point file ("-": stdin). When it cannot be used (unreadable,
// bad points, or a per-point tol column the criterion cannot use) prints
// "FILE:LINE: reason" on stderr and returns false.
bool read_job(const std::string& file, const std::string& criterion, io::PointFile& out);

// Fits pts (tols: one per point, or empty) at tol. On failure returns false
// with `error` (no "kerf: " prefix) and `status` set.
bool fit_job(const std::vector<Vec2<double>>& pts, const std::vector<double>& tols, double tol,
             const std::string& criterion, std::vector<fit::Piece<double>>& out,
             std::string& error, Status& status);

}  // namespace kerf::cli
