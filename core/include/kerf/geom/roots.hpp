// The real roots of a x^2 + b x + c = 0, for every intersection of a circle
// (or line) with a line that the fitters compute.
#pragma once

#include <cstdint>

#include "kerf/core/scalar.hpp"

namespace kerf {

// How the roots are written from s = b + sign(b) sqrt(D): the two terms
// have one sign, so s never cancels, and the other root follows from the
// product of the roots (c / a) instead of from b - sqrt(D). Both forms are
// kept because their roundings differ and results must not change.
enum class RootForm : std::uint8_t {
  half_sum,   // q = -s / 2; q / a and c / q (one root, 0, when q = 0)
  over_two_a, // x1 = -s / (2 a) and c / (a x1) (x1 alone when it is 0)
};

// Writes the real roots into out and returns how many (0..2). a = 0 is the
// linear equation (no root when b = 0 too). touch: a negative discriminant
// counts as 0 (a tangency rounding made a near miss). A discriminant that
// is not a number gives no root.
template <class S>
int quadratic_roots(S a, S b, S c, S out[2], RootForm form = RootForm::half_sum, bool touch = false) {
  if (a == S(0)) {
    if (b == S(0)) return 0;
    out[0] = -c / b;
    return 1;
  }
  S disc = b * b - S(4) * a * c;
  if (touch && disc < S(0)) disc = S(0);
  if (!(disc >= S(0))) return 0;
  const S sq = Scalar<S>::sqrt(disc);
  if (form == RootForm::over_two_a) {
    out[0] = (-b - (b < S(0) ? -sq : sq)) / (S(2) * a);
    if (out[0] == S(0)) return 1;
    out[1] = c / (a * out[0]);
    return 2;
  }
  const S q = -(b + (b < S(0) ? -sq : sq)) / S(2);
  if (q == S(0)) {
    out[0] = S(0);
    return 1;
  }
  out[0] = q / a;
  out[1] = c / q;
  return 2;
}

}  // namespace kerf
