// How far each input point is from the fitted piece that covers it: what the
// deviation panel of `kerf fit --format svg` plots and what `--format gcode`
// measures after rounding.
#pragma once

#include <vector>

#include "kerf/core/span.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::io {

// One value per point: the signed distance to the nearest piece whose
// first..last covers the point (a biarc's two arcs both cover its points),
// measured to the piece as drawn (the swept arc, the line segment).
// Positive is left of the direction of travel. A point no piece covers gets
// NaN (a bad fit; callers check).
std::vector<double> signed_deviations(Span<const Vec2<double>> points,
                                      Span<const fit::Piece<double>> pieces);

}  // namespace kerf::io
