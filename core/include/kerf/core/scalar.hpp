// Scalar operations core needs, as a traits struct so a fixed-point type can
// supply its own. The double versions use compiler builtins: no <cmath>
// (not a freestanding header) and no errno-setting library paths in the
// common cases.
#pragma once

namespace kerf {

template <class S>
struct Scalar;

template <>
struct Scalar<double> {
  static constexpr double zero() { return 0.0; }
  static constexpr double one() { return 1.0; }
  static constexpr double pi() { return 3.14159265358979323846; }
  static constexpr double from_int(long v) { return static_cast<double>(v); }
  static double sqrt(double v) { return __builtin_sqrt(v); }
  static double abs(double v) { return __builtin_fabs(v); }
  static double atan2(double y, double x) { return __builtin_atan2(y, x); }
  static double asin(double v) { return __builtin_asin(v); }
  static double cos(double v) { return __builtin_cos(v); }
  static double sin(double v) { return __builtin_sin(v); }
  static bool is_finite(double v) { return __builtin_isfinite(v); }
  static constexpr double epsilon() { return 2.220446049250313e-16; }
  static constexpr double infinity() { return __builtin_huge_val(); }
  // The power of two nearest 1 / v (v > 0): multiplying by it is exact, and
  // brings v near 1 so that squares neither overflow nor underflow.
  // The power of two a short chord's local terms are scaled by before they are
  // squared (fit/detail/chord.hpp): none, a double's exponent keeps their bits.
  static constexpr double local_scale(double) { return 1.0; }
  static double normaliser(double v) {
    int e = 0;
    __builtin_frexp(v, &e);
    return __builtin_ldexp(1.0, -e);
  }
};

template <class S>
constexpr S min_of(S a, S b) {
  return b < a ? b : a;
}
template <class S>
constexpr S max_of(S a, S b) {
  return a < b ? b : a;
}

}  // namespace kerf
