// A brute-force twin of the vertex-criterion fitter, for differential tests.
// No code shared with core/: it decides each pair i -> j on its own, by
// testing candidate circles against the plain definition, and runs a dense
// O(n^2) dynamic programme over all pairs.
//
// Pair test. The circles through p_i and p_j have centres c(t) = mid + t n on
// the perpendicular bisector (n the unit left normal of p_i -> p_j, h half
// the chord, r(t)^2 = h^2 + t^2). For an inner point p the set of t with
// | |p - c(t)| - r(t) | <= tol is a union of closed intervals whose end
// points solve |p - c| = r +- tol, i.e. with A = |p - mid|^2 - h^2 and
// B = (p - mid).n, (A - tol^2 - 2 t B)^2 = 4 tol^2 (h^2 + t^2): a quadratic
// in t. The feasible set of the pair is the intersection over the inner
// points, so if it is not empty it contains one of those roots (or it
// reaches t -> +-infinity, the line). A point counts as near the piece when
// it is near the arc itself, not only its circle (inside the arc's sweep, or
// within tol of an end): that adds, per point, the two t at which it lies on
// the ray from the centre through p_i or p_j, t = h y / (h +- x) (x along the
// chord, y across it, from the midpoint). And each step between consecutive
// points longer than 2 tol must turn forward about the centre (by less than
// half a turn): one more t per step, where the step points along the centre's
// ray. The twin tests every root, the line,
// t = 0 and t = +-sqrt(tol^2 - h^2), and as a second net `samples` values
// t = h cot(phi) for phi uniform in (0, pi). A candidate is accepted when
// every inner point passes the true test to tol (1 + 1e-9) plus 1e-12 of the
// input's scale. O(n^3 samples) overall: meant for n <= 60.
#pragma once

#include <cstddef>
#include <vector>

#include "verifier.hpp"

namespace kerf_test {

struct TwinCircle {
  bool feasible = false;
  bool line = false;  // accepted as the line through p_i and p_j
  double t = 0;       // else the accepted centre's offset along the bisector
  int dir = 0;        // and the E of the arc that passes (+1 CCW, -1 CW)
};

// Is the piece p_i -> p_j (i < j) feasible at tol? Also says which circle passed.
TwinCircle twin_pair(const std::vector<VPoint>& pts, std::size_t i, std::size_t j, double tol,
                     int samples = 2048);

struct TwinResult {
  std::size_t pieces = 0;          // the fewest pieces (0 only for fewer than 2 points)
  std::vector<std::size_t> path;   // one optimal path 0 = i_0 < ... < i_K = n - 1
};

TwinResult twin_min_count(const std::vector<VPoint>& pts, double tol, int samples = 2048);

// The twin's own pieces along a path (each pair feasible at tol), as verifier
// pieces: lines, or arcs around the accepted centre, in the accepted direction.
std::vector<VPiece> twin_pieces(const std::vector<VPoint>& pts, const std::vector<std::size_t>& path,
                                double tol, int samples = 2048);

// Diagnostics: how many pairs only the dense samples found feasible (the
// exact roots should leave them nothing to find).
struct TwinStats {
  long net_only = 0;
};
TwinStats& twin_stats();

}  // namespace kerf_test
