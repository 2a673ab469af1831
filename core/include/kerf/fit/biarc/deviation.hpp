// A certified upper bound on how far a biarc p_i -> p_j strays from the
// polyline p_i..p_j: the largest distance from a point of either arc to the
// nearest of the edges i..j-1. Computed, not sampled, like the band
// fitter's fit/band/deviation.hpp, whose arc probe it reuses.
//
// Each arc is cut where it crosses the lines of gates i..j (sorted along
// the arc). A stretch between two cuts bounded by gates
// a and b lies in one cell when the biarc is inside R, and that cell's edge
// is one of a-1, a, b-1, b. For each of those edges the largest distance
// from the stretch to the edge is found exactly (it is attained at the
// stretch's ends, where the arc crosses the normals at the edge's ends,
// where it runs parallel to the edge, or farthest from an end point; all
// are evaluated), and the smallest of these maxima bounds the stretch: a
// point's distance to the polyline is at most its distance to any edge.
// The bound is therefore never below the true deviation, and it equals it
// when each stretch is nearest its own cell's edge (the case the gates'
// bisectors give, unless a far part of the polyline folds back within tol).
// O((j - i)^2) per biarc: the fitter runs it once per biarc of the result.
#pragma once

#include <cstdint>

#include "kerf/fit/band/deviation.hpp"
#include "kerf/fit/biarc/arc.hpp"

namespace kerf::fit {

namespace biarc_detail {

// The arc's probe. An arc turning by less than 2e-7 rad is probed as its
// chord (the probe's arithmetic on a radius of 1e7 chords and more loses
// its digits) and `sagitta` is set to how far the arc leaves the chord,
// which the caller adds: every point of the arc is that close to a chord
// point, so the bound stays certified.
template <class S>
ArcProbe<S> probe_of(const ArcPart<S>& arc, bool& straight, S& sagitta) {
  const Vec2<S> c = arc.b - arc.a;
  const Vec2<S> u = c * (S(1) / band_detail::length(c));
  const int orient = arc.t.cross(c) >= S(0) ? 1 : -1;
  const Vec2<S> n = u.perp() * S(orient);
  Vec2<S> d{arc.t.dot(u), max_of(S(0), -arc.t.dot(n))};  // (cos psi, sin psi)
  straight = d.y <= S(1e-7);
  // h tan(psi / 2), h half the chord
  sagitta = straight ? band_detail::length(c) / S(2) * d.y / (S(1) + d.x) : S(0);
  if (straight) d = Vec2<S>{S(1), S(0)};
  return ArcProbe<S>(arc.a, arc.b, d, orient);
}

// One arc of the biarc; gate_a is the gate at its start (-1 when the start
// is the joint), gate_b the gate at its end (likewise).
template <class S>
S arc_deviation(const BandRegion<S>& r, std::uint32_t i, std::uint32_t j, const ArcPart<S>& part,
                int gate_a, int gate_b, const PairFrame<S>& f) {
  auto point = [&](std::uint32_t k) { return f.map(r.point(k)); };
  if (part.empty()) return S(0);
  bool straight = false;
  S sagitta{};
  const ArcProbe<S> arc = probe_of(part, straight, sagitta);
  // Crossings are ordered by ArcPart::position (a pseudo-angle on an arc),
  // or by the distance along the chord when probed as one (the probe's
  // sigma is flat along a line).
  const Vec2<S> chord = part.b - part.a;
  auto position = [&](Vec2<S> x) { return straight ? (x - part.a).dot(chord) : part.position(x); };
  const S end = position(part.b);
  // Only crossings on a gate segment bound cells (band_detail::on_gate_segment).
  auto on_gate = [&](std::uint32_t k, Vec2<S> x) {
    return band_detail::on_gate_segment(f.map(r.gate_end(k, 1)), f.map(r.gate_end(k, -1)), x);
  };
  S worst = S(0);
  Vec2<S> from = part.a;
  S at = S(0);
  int from_gate = gate_a;
  for (;;) {
    // The next crossing of a gate's line after sigma `at`.
    S best = end;
    Vec2<S> to = part.b;
    int to_gate = gate_b;
    for (std::uint32_t k = i; k <= j; ++k) {
      Vec2<S> x[2];
      const int m = arc.meet_line(point(k), r.vertex(k).b, x);
      for (int t = 0; t < m; ++t) {
        if (!on_gate(k, x[t])) continue;
        const S s = position(x[t]);
        if (s > at && s < best) {
          best = s;
          to = x[t];
          to_gate = static_cast<int>(k);
        }
      }
    }
    // The edges the stretch can lie along.
    S bound = S(-1);
    const int gates[2] = {from_gate, to_gate};
    for (const int g : gates) {
      if (g < 0) continue;
      for (int e = g - 1; e <= g; ++e) {
        if (e < static_cast<int>(i) || e >= static_cast<int>(j)) continue;
        const auto ue = static_cast<std::uint32_t>(e);
        const S d = stretch_to_edge(arc, from, to, point(ue), point(ue + 1));
        bound = bound < S(0) ? d : min_of(bound, d);
      }
    }
    if (bound < S(0)) {  // no gate at either end: every edge
      for (std::uint32_t e = i; e < j; ++e) {
        const S d = stretch_to_edge(arc, from, to, point(e), point(e + 1));
        bound = bound < S(0) ? d : min_of(bound, d);
      }
    }
    worst = max_of(worst, bound + sagitta);
    if (!(best < end)) break;
    at = best;
    from = to;
    from_gate = to_gate;
  }
  return worst;
}

}  // namespace biarc_detail

// The certified deviation of biarc b from p_i to p_j in region r, with b
// in the pair's frame f (fit/biarc/numeric.hpp; the identity in floating
// point). The result is in r's units.
template <class S>
S biarc_certified_deviation(const BandRegion<S>& r, std::uint32_t i, std::uint32_t j,
                            const Biarc<S>& b,
                            const biarc_detail::PairFrame<S>& f = biarc_detail::PairFrame<S>{}) {
  const S first = biarc_detail::arc_deviation(r, i, j, b.first, static_cast<int>(i),
                                              b.second.empty() ? static_cast<int>(j) : -1, f);
  const S second = biarc_detail::arc_deviation(r, i, j, b.second,
                                               b.first.empty() ? static_cast<int>(i) : -1, static_cast<int>(j), f);
  return f.unlength(max_of(first, second));
}

}  // namespace kerf::fit
