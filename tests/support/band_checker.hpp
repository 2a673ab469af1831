// An independent referee of kerf's band fitter (Drysdale-Rote-Sturm: fewest
// arcs through gates inside a tolerance region). No code shared with core/.
//
// The band. Vertex k has a left width L_k >= 0 and a right width R_k >= 0;
// c_k = (L_k - R_k) / 2, w_k = (L_k + R_k) / 2, n_k the unit left normal of
// edge e_k = p_k -> p_{k+1}. Against the edges first..last-1,
//   band(x) = min over k, s in [0,1] of |x - (p_k + s (p_{k+1} - p_k) + c(s) n_k)| - w(s)
// with c(s), w(s) linear between the vertices; x is inside iff band(x) <= 0.
// Per edge the term is |a - s v| - w(s) with a, v fixed: a convex function of
// s whose minimiser has a closed form (the norm's slope equals the width's
// slope), clamped to [0, 1]. Each per-edge term is also convex and 1-Lipschitz
// in x, which the certified checks below rely on.
//
// Gates (section 2 of the task): at an inner vertex the gate runs along
// b_k = unit(n_{k-1} + n_k) from p_k - gr_k b_k to p_k + gl_k b_k; end gates
// use n_0 / n_{n-2} and the halves L_k / R_k; a vertex turning within 1e-6
// rad of 180 degrees is a cusp without a gate. A piece may start or end at a
// cusp: its forward side there is then taken from the edge it leaves (start)
// or arrives on (end).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "verifier.hpp"

namespace kerf_test {

struct BandWidths {
  std::vector<double> left;   // L_k per vertex
  std::vector<double> right;  // R_k per vertex
};

BandWidths symmetric_widths(std::size_t n, double tol);           // L = R = tol
BandWidths asymmetric_widths(std::size_t n, double left, double right);
BandWidths per_vertex_widths(const std::vector<double>& tol);     // L_k = R_k = tol_k

// The band function against edges first..last-1 (first < last < pts.size()).
double band_value(VPoint x, const std::vector<VPoint>& pts, const BandWidths& widths,
                  std::size_t first, std::size_t last);

// Proves band(x) <= slack for every point x of the piece (arc or line,
// against edges piece.first..piece.last-1) by adaptive subdivision. A
// sub-piece of length len is proven when band(midpoint) <= slack - len / 2,
// or (sub-arcs turning at most pi / 2) when some single edge's term is
// <= slack - sag at both ends (that term is convex along the chord and the
// sub-arc stays within sag of its chord). Fails when a sample exceeds slack or
// the subdivision cap (depth 60, 2^22 samples) is hit. *worst (if given)
// receives the largest band value sampled. Points are computed from the start
// point, tangent and curvature (no centre), so rounding stays near 1e-16 of
// the coordinates, far below the slack the tests pass (1e-9 of the scale).
bool arc_in_band(const std::vector<VPoint>& pts, const BandWidths& widths, const VPiece& piece,
                 double slack, double* worst = nullptr);

// The same for the straight segment a -> b against edges first..last-1, e.g.
// to prove that an edge of kerf's region R lies inside the band.
bool segment_in_band(const std::vector<VPoint>& pts, const BandWidths& widths, std::size_t first,
                     std::size_t last, VPoint a, VPoint b, double slack, double* worst = nullptr);

// A certified upper bound (to 1e-9 relative, plus 1e-12 of the sub-polyline's
// scale) of the largest plain distance from a point of the piece to the
// sub-polyline p_first..p_last. Branch and bound on the same two bounds.
double band_piece_deviation(const std::vector<VPoint>& pts, const VPiece& piece);

struct BandGate {
  bool cusp = false;       // no gate: the path turns back here
  VPoint left, right;      // gate ends (p_k + gl b, p_k - gr b)
  double bx = 0, by = 0;   // unit gate direction b (to the left)
  double fx = 0, fy = 0;   // unit forward normal (towards p_{k+1}); 0 at a cusp
};

// The ideal gate at vertex k (pts.size() >= 2, consecutive points distinct).
BandGate band_gate(const std::vector<VPoint>& pts, const BandWidths& widths, std::size_t k);

struct BandReport {
  bool ok = true;
  std::string why;             // the first problem found, empty when ok
  double worst = -1e300;       // the largest band value sampled over the checked pieces
};

// One piece: index range, finite values, end points on p_first / p_last
// (1e-9 relative), equal radii, no cusp strictly inside, start and end
// tangents to the forward side of gates first and last (dot >= -1e-9), every
// inner gate cut by the piece, in order (each gate's first cut after the
// previous gate's chosen cut: ideal gates of short edges may overlap),
// and arc_in_band at slack.
BandReport check_band_piece(const std::vector<VPoint>& pts, const BandWidths& widths,
                            const VPiece& piece, double slack);

// All pieces, which must also run contiguously from 0 to n - 1.
BandReport check_band_fit(const std::vector<VPoint>& pts, const BandWidths& widths,
                          const std::vector<VPiece>& pieces, double slack);

}  // namespace kerf_test
