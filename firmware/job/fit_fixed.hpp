// The vertex and band fitters run in kerf::Fixed for `--numeric fixed`
// (kerf fit, plan, sim, run): the points and widths are rounded to the
// fixed-point grid, the fit runs there, and the pieces come back in double
// for the usual check and output. (The biarc fitter's fixed-point run is in
// job/biarc_job.cpp; it uses fixed_fit_slack below too.)
#pragma once

#include <cstdint>

#include "io/point_file.hpp"
#include "kerf/fit/band/region.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::job {

// What the fixed-point pieces may exceed tol by when checked in double: the
// rounding of the points onto the grid, and the fitter's decisions on
// points scaled into [-1, 1), where one step is 2^-32 of the largest power of
// two above the largest coordinate. 64 steps of that scale bound both.
double fixed_fit_slack(Span<const Vec2<double>> pts);

// Q31.32 holds |v| < 2^31 (mm), but the fitter scales the points by the
// inverse of a power of two at least as large as the largest coordinate, and
// that inverse saturates from 2^30 on (the fit then fails). So `kerf fit
// --numeric fixed` refuses a point at |x| or |y| >= 2^30.
inline constexpr double kFixedLimit = 1073741824.0;

// The finest tol a fixed-point fit of these points honours: 16 times
// fixed_fit_slack, so that the grid's slack stays a small part of the tol.
double fixed_min_tol(Span<const Vec2<double>> pts);

// --numeric fixed: every coordinate of `in` inside the fixed-point fit's
// range (else FILE:LINE on stderr), and a tol (0: none given) the grid
// resolves at the points' magnitude (else a usage error).
bool fixed_fits(const io::PointFile& in, double tol);

// fit_min_count (pieces == 0) or fit_min_error (pieces > 0) in Fixed; out
// holds the pieces in double.
Result<fit::Fit<double>> fit_vertex_fixed(Span<const Vec2<double>> pts, double tol,
                                          std::uint32_t pieces, fit::Method method,
                                          Span<fit::Piece<double>> out, bool tie_break = true);

// fit_band_min_count (pieces == 0) or fit_band_min_error (pieces > 0) in
// Fixed; out holds the pieces in double. The widths are per point.
Result<fit::Fit<double>> fit_band_fixed(Span<const Vec2<double>> pts,
                                        Span<const fit::BandWidth<double>> widths,
                                        std::uint32_t pieces, Span<fit::Piece<double>> out,
                                        bool tie_break = true);

}  // namespace kerf::job
