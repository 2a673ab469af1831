// The power-of-two scaling every fitter applies before it works.
#pragma once

#include "kerf/core/scalar.hpp"

namespace kerf {

// The power of two that brings m, the largest magnitude of what is scaled,
// near 1 (Scalar::normaliser); 1 for m = 0, where there is nothing to scale.
// Multiplying by a power of two is exact, so the scaled problem is the same
// problem, and kerf::Fixed keeps its bits while squares stay in range.
template <class S>
S power_of_two_scale(S m) {
  return m > S(0) ? Scalar<S>::normaliser(m) : S(1);
}

}  // namespace kerf
