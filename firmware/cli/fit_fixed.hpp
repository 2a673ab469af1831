// The vertex and band fitters run in kerf::Fixed for `--numeric fixed`
// (kerf fit, plan, sim, run): the points and widths are rounded to the
// fixed-point grid, the fit runs there, and the pieces come back in double
// for the usual check and output.
#pragma once

#include <cstdint>

#include "kerf/fit/band_region.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::cli {

// What the fixed-point pieces may exceed tol by when checked in double: the
// rounding of the points onto the grid, and the fitter's decisions on
// points scaled into [-1, 1), where one step is 2^-32 of the largest power of
// two above the largest coordinate. 64 steps of that scale bound both.
double fixed_fit_slack(Span<const Vec2<double>> pts);

// fit_min_count (pieces == 0) or fit_min_error (pieces > 0) in Fixed; out
// holds the pieces in double.
Result<fit::Fit<double>> fit_vertex_fixed(Span<const Vec2<double>> pts, double tol,
                                          std::uint32_t pieces, fit::Method method,
                                          Span<fit::Piece<double>> out);

// fit_band_min_count (pieces == 0) or fit_band_min_error (pieces > 0) in
// Fixed; out holds the pieces in double. The widths are per point.
Result<fit::Fit<double>> fit_band_fixed(Span<const Vec2<double>> pts,
                                        Span<const fit::BandWidth<double>> widths,
                                        std::uint32_t pieces, Span<fit::Piece<double>> out);

}  // namespace kerf::cli
