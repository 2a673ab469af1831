// CORDIC sine, cosine and arctangent for kerf::Fixed. Internally the vectors
// and angles carry 60 fractional bits, so the 62 rotation steps lose nothing
// visible at the result's 32 bits. The constant tables are computed by the
// compiler (consteval): there is no floating point at run time.
#include "kerf/core/fixed.hpp"

namespace kerf::fixed_trig {

namespace {

constexpr int steps = 62;
constexpr int inner_bits = 60;
constexpr int widen = inner_bits - Fixed::frac_bits;

consteval std::int64_t to_inner(double v) {
  const double s = v * 1152921504606846976.0;  // 2^60
  return static_cast<std::int64_t>(s < 0 ? s - 0.5 : s + 0.5);
}

// atan(x) for x <= 1/2 by its power series (converges by 4x per term).
consteval double atan_series(double x) {
  double term = x, sum = 0.0;
  for (int k = 0; k < 60; ++k) {
    sum += (k % 2 == 0 ? term : -term) / (2 * k + 1);
    term *= x * x;
  }
  return sum;
}

struct Table {
  std::int64_t atan[steps];
};

consteval Table make_table() {
  Table t{};
  t.atan[0] = to_inner(0.78539816339744830962);
  double x = 0.5;
  for (int i = 1; i < steps; ++i, x /= 2) t.atan[i] = to_inner(atan_series(x));
  return t;
}

constexpr Table table = make_table();
constexpr std::int64_t inner_pi = to_inner(3.14159265358979323846);
constexpr std::int64_t inner_half_pi = to_inner(1.57079632679489661923);
constexpr std::int64_t inv_gain = to_inner(0.60725293500888125617);

std::int64_t to_outer(std::int64_t inner) {
  const std::int64_t half = std::int64_t{1} << (widen - 1);
  return inner >= 0 ? (inner + half) >> widen : -((-inner + half) >> widen);
}

// The angle's cosine and sine, both at inner precision.
struct Rotated {
  std::int64_t c;
  std::int64_t s;
};

Rotated rotate(Fixed angle) {
  // Reduce to [-pi, pi] at outer precision first: |angle| may be large.
  const std::int64_t two_pi = 2 * Scalar<Fixed>::pi().raw();
  std::int64_t a = angle.raw() % two_pi;
  if (a > two_pi / 2) a -= two_pi;
  if (a < -two_pi / 2) a += two_pi;
  std::int64_t z = a * (std::int64_t{1} << widen);  // |a| <= pi: fits at 60 bits
  bool flip = false;  // rotate by the supplementary angle and negate
  if (z > inner_half_pi) {
    z -= inner_pi;
    flip = true;
  } else if (z < -inner_half_pi) {
    z += inner_pi;
    flip = true;
  }
  std::int64_t x = inv_gain, y = 0;
  for (int i = 0; i < steps; ++i) {
    const std::int64_t dx = y >> i, dy = x >> i;
    if (z >= 0) {
      x -= dx;
      y += dy;
      z -= table.atan[i];
    } else {
      x += dx;
      y -= dy;
      z += table.atan[i];
    }
  }
  return flip ? Rotated{-x, -y} : Rotated{x, y};
}

}  // namespace

Fixed sin(Fixed a) { return Fixed::from_raw(to_outer(rotate(a).s)); }
Fixed cos(Fixed a) { return Fixed::from_raw(to_outer(rotate(a).c)); }

Fixed atan2(Fixed yf, Fixed xf) {
  std::int64_t x = xf.raw(), y = yf.raw();
  if (x == 0 && y == 0) return Fixed{};
  std::int64_t z = 0;
  if (x < 0) {  // turn into the right half-plane by a quarter turn
    const std::int64_t t = x;
    if (y >= 0) {
      x = y;
      y = -t;
      z = inner_half_pi;
    } else {
      x = -y;
      y = t;
      z = -inner_half_pi;
    }
  }
  // Bring the larger component to bit 60: the gain (< 2.33 with the diagonal)
  // then stays below 2^63, and small vectors keep their full precision.
  const std::uint64_t big = static_cast<std::uint64_t>(x > (y < 0 ? -y : y) ? x : (y < 0 ? -y : y));
  const int top = 63 - fixed_detail::leading_zeros(big);
  if (top > 60) {
    x >>= top - 60;
    y >>= top - 60;
  } else {
    x *= std::int64_t{1} << (60 - top);
    y *= std::int64_t{1} << (60 - top);
  }
  for (int i = 0; i < steps; ++i) {
    const std::int64_t dx = y >> i, dy = x >> i;
    if (y > 0) {
      x += dx;
      y -= dy;
      z += table.atan[i];
    } else {
      x -= dx;
      y += dy;
      z -= table.atan[i];
    }
  }
  return Fixed::from_raw(to_outer(z));
}

}  // namespace kerf::fixed_trig
