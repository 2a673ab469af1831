// An independent referee of kerf's biarc fitter (Drysdale-Rote-Sturm,
// section 3). No code shared with core/: plain std C++ over the verifier's
// types, the band checker's band and gates, and arc_param's centre-free arcs.
//
// A biarc from p_first to p_last is two pieces (arc or line) a1, a2, both
// with first/last set to the biarc's input indices. check_biarc_fit accepts
// a fit when
//  - the biarcs run contiguously from 0 to n - 1, first < last;
//  - a1 starts on p_first, a2 ends on p_last, a1 ends where a2 starts (the
//    joint), each to 1e-9 of the input's scale; arcs have equal radii;
//  - tangent continuity: a1's start tangent is t_first, a2's end tangent is
//    t_last (the given or estimated tangents), and a1's end tangent is a2's
//    start tangent at the joint, each within `max_turn` radians (1e-9);
//  - the band: both arcs lie in the band of the widths against edges
//    first..last-1, proven by the band checker's certified subdivision;
//  - the gate rules (Definition 3.2): a1's start tangent and a2's end
//    tangent point to the forward side of gates first and last; neither arc
//    meets gate `first` or gate `last` (band_gate of `gate_widths`) except at
//    p_first and p_last (1e-9 of the scale).
//
// gate_widths: the widths of the region the fitter certifies, no wider than
// `widths` at any point (checked). Where the ideal band runs back over
// itself (a hairpin of short edges), an ideal gate reaches into the band of
// the return leg, and a biarc going down that leg crosses it there; kerf's
// region narrows the widths until its cells are convex (fit/band/region.hpp),
// and its shorter gates are the ones Definition 3.2 speaks of. Without them
// the ideal gates are used, which suits fits made in the ideal band.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "band_checker.hpp"
#include "verifier.hpp"

namespace kerf_test {

struct VBiarc {
  VPiece a1;
  VPiece a2;
};

// The unit tangent of a piece at its start (end = false) or end.
VPoint piece_tangent(const VPiece& pc, bool end);

// The angle between two unit vectors, in [0, pi].
double angle_between(VPoint a, VPoint b);

// The biarc p -> q with tangents tp, tq whose joint is m (the caller puts m
// on the joint circle); a1 is the arc from p tangent to tp through m, a2 the
// arc through m tangent to tq at q. first/last are set from i, j.
VBiarc biarc_through(VPoint p, VPoint tp, VPoint q, VPoint tq, VPoint m, std::size_t i,
                     std::size_t j);

BandReport check_biarc(const std::vector<VPoint>& pts, const std::vector<VPoint>& tangents,
                       const BandWidths& widths, const VBiarc& b, double slack,
                       double max_turn = 1e-9, const BandWidths* gate_widths = nullptr);

BandReport check_biarc_fit(const std::vector<VPoint>& pts, const std::vector<VPoint>& tangents,
                           const BandWidths& widths, const std::vector<VBiarc>& fit, double slack,
                           double max_turn = 1e-9, const BandWidths* gate_widths = nullptr);

}  // namespace kerf_test
