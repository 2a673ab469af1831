// The fits of recent parts, kept per thread. CAM output cuts the same
// contour at several depths (pcb2gcode's outline passes, a calibration
// square's layers): a part whose points, tol, criterion and tie-break repeat
// an earlier one's, bit for bit, gets that fit's pieces again instead of a
// new search. A fit is a function of those alone, so the output is the same
// bytes either way.
#pragma once

#include <string>
#include <vector>

#include "job/criterion.hpp"
#include "kerf/fit/fit.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::weld::detail {

// job::fit_job(pts, {}, tol, criterion, out, error, status, floating,
// tie_break, &split), from the memo when it has it.
bool fit_memo(const std::vector<Vec2<double>>& pts, double tol, job::Criterion criterion, double tie_break,
              std::vector<fit::Piece<double>>& out, std::string& error, bool& split);

}  // namespace kerf::weld::detail
