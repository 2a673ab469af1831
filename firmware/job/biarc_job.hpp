// The biarc criterion for the commands (`kerf fit --criterion biarc`, and
// `kerf plan` / `kerf sim` through fit_job): core's fewest G1 biarcs
// (kerf/fit/biarc.hpp) within a symmetric --tol, on given or estimated
// tangents, each biarc checked before it is used.
#pragma once

#include <string>
#include <vector>

#include "kerf/core/status.hpp"
#include "kerf/fit/biarc.hpp"

namespace kerf::job {

// Fits one path. tangents: one unit vector per point, or empty to estimate
// them (fit/biarc/tangent.hpp). On failure returns false with `error` (no "kerf: "
// prefix) and `status` set. fixed: the points, tangents (estimated in
// kerf::Fixed too when not given) and tol are rounded to Q31.32 and the
// fit runs there (exact sets only); the biarcs come back in double and are
// checked with the fixed-point allowance (job/fit_fixed.hpp).
bool fit_biarc_path(const std::vector<Vec2<double>>& pts, const std::vector<Vec2<double>>& tangents,
                    double tol, std::vector<fit::BiarcPiece<double>>& out, fit::Fit<double>& fit,
                    std::string& error, Status& status, bool fixed = false);

// What a fitted path must satisfy (a check of the output, not a proof): each
// biarc starts on p_first with the point's tangent, its arcs meet at the
// joint with one tangent (1e-9 rad), it ends on p_last with that point's
// tangent, and every point p_first..p_last lies within tol of the biarc.
// A part that is a point (the joint on an end, one circle with both
// tangents) has no tangent: the other part must then meet both.
// slack (fixed-point fits: fixed_fit_slack) is added to every distance,
// and 2 slack / the arc's chord to every angle (an arc's tangent comes from
// its centre and ends, each that close); the end tangent also gets the
// first arc's (the second arc starts with the first's end tangent).
// Empty when fine, else what is wrong.
std::string check_biarcs(const std::vector<Vec2<double>>& pts,
                         const std::vector<Vec2<double>>& tangents, double tol,
                         const std::vector<fit::BiarcPiece<double>>& pieces, double slack = 0.0);

}  // namespace kerf::job
