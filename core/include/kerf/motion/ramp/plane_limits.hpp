// The acceleration in the plane, in step units (see lookahead.hpp: a step x
// is the path length of one period, A = accel * period^2, B = jerk * period^3).
//
// Two consecutive steps x1, x2 along the path are the chords c1, c2; the
// machine's acceleration over that period is (c2 - c1) / T^2, and
//   |c2 - c1|^2 = (x2 - x1)^2 + 4 x1 x2 sin^2(phi / 2),
// phi being the angle between the chords: the turns of the joints between
// them plus the arc angle, phi <= sum(turn) + x_hi * kappa (x_hi = max(x1,
// x2), kappa the largest curvature they touch). With s = 2 sin(theta / 2) for
// a joint's turn theta, the normal part is at most
//   c = x_hi * (sum(s) + x_hi * kappa),
// and the rule for every period is the exact one:
//   (x2 - x1)^2 + c^2 <= A^2, i.e. the tangential change is at most
//   sqrt(A^2 - c^2).
// Speeds are capped so that c <= k A (k = kShare below) on every arc and at
// every joint: the tangential share sqrt(1 - k^2) A > 0 is left for ramping,
// so the head can always brake. k = 0.85: the steady speed on a tight arc is
// sqrt(k) = 92 % of sqrt(accel r) while braking there keeps 53 % of accel;
// an isolated small circle from rest to rest then takes about 1.12 times
// the time that the plain limits allow (0.8: 1.13, 0.9: 1.13, 0.95: 1.17).
//
// Jerk (S-curve): where the curvature jumps at a joint, the normal
// acceleration jumps within one period: x^2 |d kappa| <= B / 2 bounds that
// step of the jerk (arcs and lines cannot join with continuous curvature, so
// the speed at the joint is what bounds it). A tangent jump is a velocity
// step, so its jerk is unbounded at any speed above zero (x s <= B would ask
// for 2 um/s at a 15 degree corner with jerk 2e4 at 0.25 ms): there the rule
// is the acceleration's. On an arc at
// steady speed the acceleration vector turns: |jerk| = v^3 kappa^2, capped at
// B / 2; while ramping on an arc the normal acceleration changes by
// 3 a_t v kappa, so the tangential change is held to B / (6 x kappa).
#pragma once

#include "kerf/core/scalar.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::motion {

inline constexpr double kShare = 0.85;  // of A, at most, for the normal part

// 2 sin(theta / 2) for the turn between unit tangents t_out and t_in.
template <class S>
S turn_chord(Vec2<S> t_out, Vec2<S> t_in) {
  const S one_minus = S(1) - t_out.dot(t_in);  // = 2 sin^2(theta / 2), in [0, 2]
  if (!(one_minus > S(0))) return S(0);
  return S(2) * Scalar<S>::sqrt(one_minus / S(2));
}

// The largest x with x (s + x kappa) <= budget (infinity when s and kappa are 0).
template <class S>
S joint_step(S s, S kappa, S budget) {
  if (!(kappa > S(0))) return s > S(0) ? budget / s : Scalar<S>::infinity();
  // kappa x^2 + s x - budget = 0, the positive root, written without cancellation
  return S(2) * budget / (s + Scalar<S>::sqrt(s * s + S(4) * kappa * budget));
}

// The step cap on a curve of curvature kappa (> 0): x^2 kappa <= k A, and
// with jerk (b > 0) x^3 kappa^2 <= b / 2.
template <class S>
S curve_step_cap(S kappa, S a, S b) {
  if (!(kappa > S(0))) return Scalar<S>::infinity();
  S x = Scalar<S>::sqrt(S(kShare) * a / kappa);
  if (b > S(0)) {
    const S c = b / (S(2) * kappa * kappa);  // x^3 <= c
    if (x * x * x > c) {  // Newton from above: decreasing, converges
      for (int i = 0; i < 60; ++i) {
        const S next = (S(2) * x + c / (x * x)) / S(3);
        if (!(next < x)) break;
        x = next;
      }
    }
  }
  return x;
}

// The speed limit at a joint with chord turn s, between curvatures k_in and
// k_out (signed: + left, - right), in step units.
template <class S>
S joint_step_limit(S s, S k_in, S k_out, S a, S b) {
  const S k_max = max_of(Scalar<S>::abs(k_in), Scalar<S>::abs(k_out));
  S w = joint_step(s, k_max, S(kShare) * a);
  if (b > S(0)) w = min_of(w, joint_step(S(0), Scalar<S>::abs(k_out - k_in), b / S(2)));
  return w;
}

// What is left of A for the change of the step when the normal part is c
// (clamped to k A: speeds are capped so that it is no more; see above).
template <class S>
S tangential_step(S c, S a) {
  const S n = min_of(c, S(kShare) * a);
  return Scalar<S>::sqrt(a * a - n * n);
}

}  // namespace kerf::motion
