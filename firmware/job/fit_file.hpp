// `kerf fit` on a whole point file, once its options are checked
// (app/fit_command.cpp, app/fit_biarc_command.cpp): read, fitted path by
// path, checked (job/check_fit.hpp), written in --format, and the
// summary line on stderr.
#pragma once

#include <cstdint>

#include "job/criterion.hpp"
#include "job/fit_options.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::job {

struct FileFit {
  Criterion criterion = Criterion::vertex;  // vertex or band
  bool fixed = false;                       // --numeric fixed
  fit::Method method = fit::Method::optimal;
  std::uint32_t pieces = 0;  // > 0: the smallest tol for this many pieces
  double tol = 0.0;          // 0 with --pieces
  bool tie_break = true;     // --tie-break none: false
  double feed = 1000.0;      // gcode, mm/min
};

// Returns the exit code (io/options.hpp).
int fit_file(const FitOptions& opts, const FileFit& f);

// The same for --criterion biarc (job/biarc_job.hpp), at --tol, on the
// file's tangents or (estimate) estimated ones, printed as two arcs per biarc.
int fit_biarc_file(const FitOptions& opts, bool fixed, double tol, bool estimate, double feed);

}  // namespace kerf::job
