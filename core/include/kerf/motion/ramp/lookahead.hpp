// The ramp arithmetic, in the interpolator's own units: a "step" is the path
// length advanced in one servo period (mm), and A = accel * period^2 is the
// most a step may differ from the one before. Working in whole periods (not in
// continuous time) is what lets the interpolator land exactly on a stop point
// without ever exceeding the acceleration limit: braking from step X runs the
// steps X, X - A, X - 2A, ... and its length is a closed-form sum.
#pragma once

#include "kerf/core/scalar.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::motion {

// Path length covered by the steps X, X - A, X - 2A, ... that are still
// faster than W, i.e. how far ahead of a point whose step limit is W a step
// of X must start braking (0 when X <= W).
template <class S>
S braking_length(S x, S w, S a) {
  if (!(x > w)) return S(0);
  // m + 1 terms, m = ceil((x - w) / a) - 1
  long m = static_cast<long>((x - w) / a);
  if (w + a * Scalar<S>::from_int(m) >= x) --m;  // x - w an exact multiple of a
  const S n = Scalar<S>::from_int(m + 1);
  return n * x - a * Scalar<S>::from_int(m) * n / S(2);
}

// The largest step X with braking_length(X, W, A) <= D: the fastest this
// period may go while a point D ahead can still be reached at step W or less.
// braking_length is increasing in X, and on each bracket (W + mA, W + (m+1)A]
// it is (m+1) X - A m (m+1) / 2, so the answer is found by locating the
// bracket with one square root and then solving a linear equation.
template <class S>
S max_step_before(S d, S w, S a) {
  if (!(d > w)) return w;  // any faster first step would already pass the point too fast
  // h(m) = (m+1) W + A m (m+1)/2 is braking_length at the bottom of bracket m;
  // the bracket holding the answer is the last m with h(m) < D.
  const S b = w + a / S(2);
  const S root = (Scalar<S>::sqrt(b * b + S(2) * a * (d - w)) - b) / a;
  long m = static_cast<long>(root);
  const auto h = [&](long k) {
    const S n = Scalar<S>::from_int(k + 1);
    return n * w + a * Scalar<S>::from_int(k) * n / S(2);
  };
  while (m > 0 && !(h(m) < d)) --m;
  while (h(m + 1) < d) ++m;
  const S n = Scalar<S>::from_int(m + 1);
  const S x = d / n + a * Scalar<S>::from_int(m) / S(2);
  // The top of the bracket, less a few ulps: exactly at the top the last
  // braking step would be W itself, which rounding may put just above W.
  const S top = (w + a * n) * (S(1) - S(8) * Scalar<S>::epsilon());
  return x < top ? x : top;
}

}  // namespace kerf::motion
