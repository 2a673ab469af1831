// A fit written as G-code (`kerf fit --format gcode`): per path a G0 to its
// start, then one G1 per line piece and one G2/G3 per arc piece, with I/J
// relative to the arc's (rounded) start, in mm (G21 G90 G17).
//
// Rounding: every number is written with `decimals` digits after the point.
// A controller draws an arc from its rounded start around start + I/J to its
// rounded end, so the written piece is not the fitted one; rounded_pieces()
// rebuilds the pieces as written and written_deviation() measures them
// against the points, so that the caller can choose enough decimals.
#pragma once

#include <string>
#include <vector>

#include "kerf/core/span.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::io {

struct GcodeFit {
  // Pieces in job order; first/last index into `points` (the whole job).
  Span<const fit::Piece<double>> pieces{};
  Span<const Vec2<double>> points{};
  double feed = 1000.0;   // mm/min, on the first feed move of each path
  int decimals = 4;       // digits after the point
  std::string comment;    // first line, after "; "
};

std::string format_fit_gcode(const GcodeFit& g);

// The pieces as the G-code above draws them: rounded start and end, centre at
// the rounded start plus the rounded I/J offset. A piece starts where the
// previous one ended (rounded), unless it begins a new path (a G0).
std::vector<fit::Piece<double>> rounded_pieces(const GcodeFit& g);

// The largest distance of a point to the written piece that covers it
// (points first..last of each piece; to the circle through the drawn arc's
// start, widened by the difference between its start and end radius, or to
// the line).
double written_deviation(const GcodeFit& g);

// The fewest decimals in [lo, 12] whose written deviation is within tol (12
// when none is). 10^-12 mm is far below any machine's resolution.
int gcode_decimals(GcodeFit g, double tol, int lo);

}  // namespace kerf::io
