// A last look at a fit before it is printed for a machine to cut: do the
// pieces chain from the first point to the last, start and end on their
// points, and keep every point in between within the tolerance? It is
// measured here independently of the fitter, with the vertex criterion's
// distance (to the piece's full circle, or its line), plus that an arc
// passes its points in order (not round the circle more than once, nor
// backwards: the fitters test the circle, not the order). A failure is a bug or
// a numeric breakdown in the fitter, and no output must be written.
#pragma once

#include <string>

#include "kerf/core/span.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::job {

// Empty when the fit is sound, else what is wrong. `tol` is the tolerance the
// fit must meet; a relative 1e-6 of it (and 1e-12 of the points' extent) is
// allowed for rounding.
std::string check_fit(Span<const Vec2<double>> pts, Span<const fit::Piece<double>> pieces,
                      double tol);

}  // namespace kerf::job
