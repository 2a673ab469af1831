// A brute-force twin of kerf's band fitter over a GIVEN region R with gates
// (Drysdale-Rote-Sturm, Definition 2.2), for differential tests. No code
// shared with core/: every pair i -> j is decided by testing candidate arcs
// against the plain definition, and a dense DP over all pairs gives the
// fewest pieces. Meant for n <= 40..60; obviously correct rather than fast.
//
// A piece p_i -> p_j is valid when
//  (a) for every i < m < j the full circle (or line) meets the closed gate
//      segment m exactly once, there on the arc, moving to its forward side;
//  (b) the arc crosses no segment of chain_left[k] / chain_right[k],
//      k = i..j-1. Touching is allowed: an intersection within 1e-12 of the
//      input's scale of the arc's end points or of the segment's ends, or a
//      contact whose circle dips less than that beyond the segment's line,
//      counts as touching;
//  (c) the start tangent points to the forward side of gate i, the end
//      tangent to the forward side of gate j (dot >= -1e-12).
// Forward side of gate k: the side of its line that p_{k+1} is on (gate n-1:
// away from p_{n-2}); a gate of zero length falls back to unit(u_{k-1} + u_k).
//
// Candidates: the circles through p_i and p_j by half sweep psi in [0, pi)
// per orientation (psi = 0 is the line): psi = 0; the circle through each gate
// end and chain vertex of cells i..j-1; start or end tangent parallel to gate i
// or j; the midpoints between consecutive sorted candidates; a uniform grid of
// 2048 per orientation.
#pragma once

#include <cstddef>
#include <vector>

#include "verifier.hpp"

namespace kerf_test {

struct BandRegion {
  std::vector<VPoint> pts;                    // p_0..p_{n-1}
  std::vector<VPoint> gate_left, gate_right;  // per vertex: gate end on the left / right of the path
                                              // (p_k lies on the gate segment; a zero-length half
                                              // has its end == p_k)
  std::vector<std::vector<VPoint>> chain_left, chain_right;
  // per cell k = 0..n-2: the boundary of R between gate k and gate k+1 on that side, a polyline
  // from gate_left[k] to gate_left[k+1] (both included), resp. gate_right[k] to gate_right[k+1]
};

// Is there a valid piece p_i -> p_j (i < j)? If so and piece_out is given,
// it receives one (a VPiece with centre and direction, or a line).
bool twin_pair_valid(const BandRegion& region, std::size_t i, std::size_t j,
                     VPiece* piece_out = nullptr);

// The fewest valid pieces from p_0 to p_{n-1}, or -1 when there is no chain
// of valid pieces (or the region is malformed). pieces_out, if given,
// receives one optimal chain.
int twin_min_pieces(const BandRegion& region, std::vector<VPiece>* pieces_out = nullptr);

}  // namespace kerf_test
