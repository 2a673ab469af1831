// kerf's biarc fitter: the fewest G1-continuous biarcs from input point to
// input point, each inside the tolerance region R (Drysdale, Rote, Sturm,
// section 3). A biarc p_i -> p_j starts with the tangent t_i and ends with
// t_j, so consecutive biarcs share their tangent at the input points used,
// and the two arcs of a biarc share theirs at the joint: the cut has no
// corner anywhere. Tangents are given or estimated (fit/biarc/tangent.hpp).
//
// Per pair, the valid joints on the joint circle J (fit/biarc/arc.hpp) are
// computed exactly, as intervals of J (fit/biarc/joints.hpp): not sampled,
// so no valid pair is missed and the count is the fewest. Far pairs are
// skipped only when a proven bound on how far a biarc can reach rules them
// out (fit/biarc/reach.hpp). The fewest biarcs are a shortest path over the
// valid pairs (breadth-first over the DAG, O(n) memory); each biarc of the
// path then gets the joint inside its valid set that minimises its
// (sampled) deviation from the polyline, and its certified deviation
// (fit/biarc/deviation.hpp) is reported.
// Everything runs in caller-provided storage; see BiarcWorkspace.
#pragma once

#include <cstdint>

#include "kerf/core/span.hpp"
#include "kerf/core/status.hpp"
#include "kerf/fit/band/region.hpp"
#include "kerf/fit/biarc/arc.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::fit {

template <class S>
struct BiarcPiece {
  std::uint32_t first = 0;  // index of the start point
  std::uint32_t last = 0;   // index of the end point
  Segment<S> arc[2]{};      // p_first -> joint, joint -> p_last
  Vec2<S> joint{};
  Vec2<S> tangent[3]{};     // unit tangents at p_first, the joint, p_last
  S error{};                // certified bound on the distance from the polyline p_first..p_last
};

// The most joints sampled per valid interval when the joint is chosen.
inline constexpr std::uint32_t kBiarcMaxSamples = 64;

template <class S, int Cap>
class JointSet;

// A pair's valid joints found another way than kerf's exact sets
// (fit/biarc/joints.hpp): the tests pass the paper's construction through the
// visibility regions W_i, W~_j (tests/support/biarc_visibility.hpp) to
// cross-check the two. Floating point only.
using BiarcJointsFn = bool (*)(const BandRegion<double>& r, std::uint32_t i, std::uint32_t j,
                               Vec2<double> ti, Vec2<double> tj, JointSet<double, 128>& out);

struct BiarcOptions {
  std::uint32_t samples = 16;  // joints scored per valid interval (1..64), then a golden-section search
  // Test every pair, ignoring the proven reach bound of fit/biarc/reach.hpp
  // (slow; the tests use it to show the bound changes no count).
  bool exact = false;
  // nullptr: kerf's exact sets. Otherwise the caller's sets decide alone
  // (no quick joints), so that the referee is what the tests and the
  // benchmark measure; kerf::Fixed refuses them (Status::invalid_argument).
  BiarcJointsFn joints = nullptr;
};

constexpr std::size_t biarc_workspace_words(std::size_t n) { return 4 * n; }

template <class S>
struct BiarcWorkspace {
  Span<std::uint32_t> words;        // >= biarc_workspace_words(n)
  Span<BandVertex<S>> vertices;     // >= n: the region
  Span<Vec2<S>> points;             // >= n: the points as the fitter scales them
};

// Fewest biarcs inside the region R of `widths` (one per point, both sides
// > 0; fit/band/region.hpp), with unit tangents (one per point). Needs
// out.size() >= the count (n - 1 suffices). fit.max_error is the largest
// BiarcPiece::error, fit.tol the largest width.
//
// In kerf::Fixed the points are scaled by a power of two into [-1, 1) and
// each pair is tested in its own frame (fit/biarc/numeric.hpp), like the
// band fitter; the pieces come back in the input's units. A fixed-point
// arc that turns by less than 2^-24 rad, or whose centre would leave the
// range, is output as its chord (ArcPart::segment).
template <class S>
Result<Fit<S>> fit_biarc_min_count(Span<const Vec2<S>> pts, Span<const Vec2<S>> tangents,
                                   Span<const BandWidth<S>> widths,
                                   BiarcOptions opts, BiarcWorkspace<S> ws,
                                   Span<BiarcPiece<S>> out);

// The largest sampled distance of biarc b (from p_i to p_j; used to choose the joint) from the
// polyline p_i..p_j.
template <class S>
S biarc_deviation(Span<const Vec2<S>> pts, std::uint32_t i, std::uint32_t j, const Biarc<S>& b);

}  // namespace kerf::fit
