// A point file's cut paths fitted one by one into a controller Job: each
// path becomes a chain of arcs and lines at the cut feed, pierced at its
// first point. Shared by `kerf sim` and `kerf run`.
#pragma once

#include <string>
#include <vector>

#include "control/job.hpp"
#include "io/point_file.hpp"
#include "kerf/core/status.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::cli {

struct FittedJob {
  control::Job job;
  std::vector<fit::Piece<double>> pieces;  // in job order
  std::vector<std::size_t> piece_path;     // the path of each piece
};

// On failure returns false with `error` ("path N (line L): reason") and `status`.
bool fit_paths(const io::PointFile& in, const std::string& criterion, double tol, double feed_mm_s,
               FittedJob& out, std::string& error, Status& status);

}  // namespace kerf::cli
