// A monotone necessary condition for the vertex criterion, used to stop
// looking at a start point i once no later end point can work.
//
// If p_i -> p_j is feasible, one circle C through p_i passes within eps of
// every p_k, i < k <= j. So for every j' <= j and any three points a, b, c in
// (i, j'], "some circle through p_i passes within eps of p_a, p_b and p_c"
// holds. The guard checks that for (a, b, c) = the thirds of (i, j'] and j'
// itself, at the j' it is asked about, and stays false once it fails: the
// conjunction over the j' seen so far is necessary for every later j and can
// only shrink as j grows. Skipping some j' only weakens it, which stays safe.
//
// The check itself: map q = p - p_i to z = q / (|q|^2 - eps^2). Circles and
// lines through p_i become lines, and "within eps" (for radii >= eps) becomes
// "the line meets the disc of radius eps / (|q|^2 - eps^2) around z". A line
// meets three discs iff the three pairwise conditions |beta.(z_a - z_b)| <=
// e_a + e_b share a unit normal beta, which is an intersection of three arcs
// of directions (mod pi), decided by testing the arcs' end points. A circle through p_i with r < eps keeps every
// point within 3 eps of p_i, so a point that close makes the guard pass.
#pragma once

#include <cstdint>
#include <type_traits>  // freestanding

#include "kerf/geom/vec2.hpp"

namespace kerf::fit {

template <class S>
bool circle_through_near_three(Vec2<S> origin, const Vec2<S> pts[3], S eps) {
  using M = Scalar<S>;
  Vec2<S> z[3];
  S e[3];
  for (int k = 0; k < 3; ++k) {
    const Vec2<S> q = pts[k] - origin;
    const S s = q.norm2() - eps * eps;
    if (!(q.norm2() > S(9) * eps * eps)) return true;
    const S inv = S(1) / s;
    z[k] = q * inv;
    // In floating point a few ulps off eps / s, within the slack below.
    if constexpr (std::is_floating_point_v<S>) e[k] = eps * inv;
    else e[k] = eps / s;
  }
  if constexpr (std::is_floating_point_v<S>) {
    // Quick yes: the line through z[0] and z[2] meets disc 1 (no root).
    // (A yes is always safe here: the guard only drops starts.)
    const Vec2<S> dz = z[2] - z[0];
    const S cr = dz.cross(z[1] - z[0]);
    if (cr * cr <= e[1] * e[1] * dz.norm2()) return true;
  }
  // Constraint c: |beta . w[c]| <= lim[c]. If the allowed directions of all
  // three meet, the first direction of their intersection is an end point of
  // one constraint's arc, so checking the (at most six) end points decides.
  // Rounding: z, w and beta carry relative errors of a few ulps, so |beta.w|
  // is known only to within a few ulps of |z_a| + |z_b|. That much slack is
  // added to each limit: a guard may pass wrongly, never fail wrongly.
  Vec2<S> w[3];
  S lim[3];
  S slack[3];
  S w_len[3];
  // Square roots and divisions were most of the guard's time: the slack
  // takes |z|'s bound |x| + |y| (only more slack), and a constraint's length
  // is taken only once its square shows it binds.
  const S z_len[3] = {M::abs(z[0].x) + M::abs(z[0].y), M::abs(z[1].x) + M::abs(z[1].y),
                      M::abs(z[2].x) + M::abs(z[2].y)};
  const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
  int active = 0;
  for (const auto& pr : pairs) {
    w[active] = z[pr[0]] - z[pr[1]];
    lim[active] = e[pr[0]] + e[pr[1]];
    slack[active] = S(256) * M::epsilon() * (z_len[pr[0]] + z_len[pr[1]] + lim[active]);
    const S bound = lim[active] + slack[active];
    if (!(w[active].norm2() > bound * bound)) continue;
    w_len[active] = w[active].norm();
    if (w_len[active] > bound) ++active;
  }
  if (active < 2) return true;  // one arc alone is never empty
  for (int c = 0; c < active; ++c) {
    const S inv = S(1) / w_len[c];
    const Vec2<S> u = w[c].perp() * inv;  // |beta . w| = 0 along u
    // (In floating point a few ulps off lim / len, within the slack.)
    const S k = std::is_floating_point_v<S> ? lim[c] * inv : lim[c] / w_len[c];
    const S co = M::sqrt(S(1) - k * k);
    const Vec2<S> ends[2] = {{u.x * co - u.y * k, u.y * co + u.x * k},
                             {u.x * co + u.y * k, u.y * co - u.x * k}};
    for (const Vec2<S>& beta : ends) {
      bool all = true;
      for (int d = 0; d < active && all; ++d)
        all = M::abs(beta.dot(w[d])) <= lim[d] + slack[d];
      if (all) return true;
    }
  }
  return false;
}

// Stateless apart from the caller's "alive" flag: check(i, j) is evaluated
// at the j the search asks about and the caller keeps i dead once it fails.
template <class S>
bool prefix_guard(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j, S eps) {
  if (j < i + 3) return true;
  const std::uint32_t span = j - i;
  const Vec2<S> three[3] = {pts[i + span / 3], pts[i + (2 * span) / 3], pts[j]};
  return circle_through_near_three(pts[i], three, eps);
}

}  // namespace kerf::fit
