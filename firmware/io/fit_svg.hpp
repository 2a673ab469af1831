// The fit plot (`kerf fit --format svg`): one self-contained SVG, like
// Figure 3 of the ESGI'104 report.
//
// Top panel (id "xy"): the XY view at equal scale, y up. The tolerance band
// as the input polyline stroked 2 * tol wide with round joins and caps (the
// points within tol of the polyline: the band criterion's band, drawn
// <path class="band">, one per path), each fitted piece as its own
// <path class="piece"> coloured per piece, and the input points as
// <circle class="pt">.
// Bottom panel (id "deviation"): the signed distance of each point to its
// piece (left of travel positive) against the distance along the input
// polyline: one <polyline class="dev"> with a vertex per input point, and the
// limits +tol_left and -tol_right as <line class="limit">.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "kerf/core/span.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::io {

struct FitPlot {
  Span<const Vec2<double>> points{};           // the whole job
  std::vector<std::size_t> path_begin;         // first point of each path (empty: one path)
  Span<const fit::Piece<double>> pieces{};     // first/last index into points
  double tol_left = 0.0;                       // the band's half-widths, mm
  double tol_right = 0.0;
  std::string title;
};

std::string format_fit_svg(const FitPlot& plot);

}  // namespace kerf::io
