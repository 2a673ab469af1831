// Arcs and lines by start point, unit start tangent and signed curvature, for
// the band checker and the band twin. This form has no centre, so it stays
// accurate for huge radii and turns into the line at curvature 0:
//   x(sigma) = s + T sin(k sigma)/k + N (1 - cos(k sigma))/k,  N = left normal of T,
// sigma the arc length from s, k > 0 counter-clockwise, k < 0 clockwise.
#pragma once

#include "verifier.hpp"

namespace kerf_test {

struct ArcParam {
  VPoint s;            // start
  double tx = 1, ty = 0;  // unit start tangent
  double kappa = 0;    // signed curvature (1 / radius), 0 for a line
  double length = 0;   // arc length from s to the end
};

// The arc (or line) of a verifier piece: start point, tangent from the centre
// and direction, length from the end point (a closed arc is a full circle).
ArcParam arc_of_piece(const VPiece& piece);

VPoint arc_point(const ArcParam& a, double sigma);
VPoint arc_tangent(const ArcParam& a, double sigma);

// The largest distance of a sub-arc of length ds from its chord; only
// meaningful for |kappa| ds <= pi (callers use it up to pi / 2).
double arc_sag(const ArcParam& a, double ds);

// The arc length from s to a point x of the full circle (or line), in
// [0, 2 pi / |kappa|) for arcs. For x off the circle it is approximate.
double arc_position(const ArcParam& a, VPoint x);

// The parameters t of the points p + t (q - p) of the infinite line through
// p and q that lie on the full circle (or line) of a. Returns how many (0..2);
// a double root is returned twice. A segment along a line piece has none.
int circle_line_roots(const ArcParam& a, VPoint p, VPoint q, double t[2]);

}  // namespace kerf_test
