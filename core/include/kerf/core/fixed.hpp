// kerf::Fixed: a signed Q31.32 fixed-point number (int64 raw value, 32
// fractional bits), for cores without a floating-point unit.
//
//   resolution  2^-32 ~ 2.33e-10 (mm, in the CLI's units: 0.23 picometre)
//   range       [-2^31, 2^31 - 2^-32] ~ +-2.1e9 (+-2147 km in mm)
//
// So +-10 m at 1 um (+-1e4 mm at 1e-3 mm) is covered with room for squares:
// a squared distance across a 20 m part (8e8 mm^2) still fits. The fitter
// scales its points by a power of two into [-1, 1) (Scalar::normaliser), so
// its fourth-power intermediates stay below 2^6 and a coordinate keeps 32
// bits relative to the part size: 10 m parts resolve to ~5 nm.
//
// Overflow saturates: a result out of range becomes max() or lowest(), which
// Scalar<Fixed> reports as +-infinity (is_finite is false), just as a double
// overflows to inf. Division by zero saturates likewise (0/0 gives max()).
// Nothing here uses floating point at run time: products go through 32-bit
// limbs (no __int128, so 32-bit targets build it), division and square root
// are integer shift-subtract loops. The double constructor is consteval:
// literals such as S(1e-9) in templated code are converted by the compiler.
#pragma once

#include <cstdint>
#include <type_traits>  // freestanding

#include "kerf/core/scalar.hpp"

namespace kerf {

namespace fixed_detail {

// An unsigned 128-bit value as two 64-bit halves; only what Fixed needs.
struct U128 {
  std::uint64_t hi = 0;
  std::uint64_t lo = 0;
};

// a * b through four 32x32->64 products, which every 32-bit target has.
constexpr U128 mul_64x64(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t a0 = a & 0xffffffffu, a1 = a >> 32;
  const std::uint64_t b0 = b & 0xffffffffu, b1 = b >> 32;
  const std::uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  const std::uint64_t mid = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
  U128 r;
  r.lo = (p00 & 0xffffffffu) | (mid << 32);
  r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
  return r;
}

constexpr int leading_zeros(std::uint64_t v) {
  return v == 0 ? 64 : __builtin_clzll(v);
}

// n / d for a 128-bit n and 64-bit d != 0; false when the quotient needs
// more than 64 bits. Restoring division, one quotient bit per step.
constexpr bool div_128_64(U128 n, std::uint64_t d, std::uint64_t& q) {
  if (n.hi >= d) return false;
  std::uint64_t rem = n.hi;
  q = 0;
  for (int i = 63; i >= 0; --i) {
    const bool carry = (rem >> 63) != 0;  // the shifted remainder has 65 bits
    rem = (rem << 1) | ((n.lo >> i) & 1u);
    if (carry || rem >= d) {
      rem -= d;
      q |= std::uint64_t{1} << i;
    }
  }
  return true;
}

// floor(sqrt(n)) for a 128-bit n: the bit-by-bit method on 64-bit halves.
constexpr std::uint64_t isqrt_128(U128 n) {
  U128 rem{};      // running remainder (< 2^66 fits: root < 2^64)
  std::uint64_t root = 0;
  for (int i = 63; i >= 0; --i) {
    // bring down two bits of n
    const std::uint64_t two = i >= 32 ? (n.hi >> ((i - 32) * 2)) & 3u : (n.lo >> (i * 2)) & 3u;
    rem.hi = (rem.hi << 2) | (rem.lo >> 62);
    rem.lo = (rem.lo << 2) | two;
    // trial = 4 * root + 1, as 128 bits (root < 2^63 here: at most 66 bits)
    U128 trial{root >> 62, (root << 2) | 1u};
    const bool fits = rem.hi > trial.hi || (rem.hi == trial.hi && rem.lo >= trial.lo);
    root <<= 1;
    if (fits) {
      const std::uint64_t borrow = rem.lo < trial.lo ? 1u : 0u;
      rem.lo -= trial.lo;
      rem.hi -= trial.hi + borrow;
      root |= 1u;
    }
  }
  return root;
}

#if defined(__SIZEOF_INT128__) && !defined(KERF_FIXED_PORTABLE)
__extension__ typedef unsigned __int128 Wide;  // __extension__: -Wpedantic accepts it

// floor(sqrt(r * 2^32)) by Newton's method from above, on 64-bit hosts: the
// same result as isqrt_128 in a handful of divisions.
inline std::uint64_t isqrt_newton(std::uint64_t r) {
  if (r == 0) return 0;
  const fixed_detail::Wide n = static_cast<fixed_detail::Wide>(r) << 32;
  const int bits = 64 - leading_zeros(r) + 32;
  fixed_detail::Wide x = static_cast<fixed_detail::Wide>(1) << ((bits + 1) / 2);  // >= sqrt(n)
  for (;;) {
    const fixed_detail::Wide y = (x + n / x) / 2;
    if (y >= x) break;
    x = y;
  }
  return static_cast<std::uint64_t>(x);
}
#endif

}  // namespace fixed_detail

class Fixed {
 public:
  static constexpr int frac_bits = 32;
  static constexpr std::int64_t one_raw = std::int64_t{1} << frac_bits;
  static constexpr std::int64_t max_raw = INT64_MAX;
  static constexpr std::int64_t lowest_raw = -INT64_MAX;  // symmetric: -max() is lowest()

  constexpr Fixed() = default;
  // Integers convert exactly; beyond the range they saturate.
  template <class I>
    requires(std::is_integral_v<I> && !std::is_same_v<I, bool>)
  constexpr Fixed(I v) : raw_(from_integer(static_cast<std::int64_t>(v))) {}
  // Only at compile time: S(1e-9) in the core's templates. Rounds to nearest.
  consteval Fixed(double v) : raw_(from_double_ct(v)) {}

  static constexpr Fixed from_raw(std::int64_t r) {
    Fixed f;
    f.raw_ = r;
    return f;
  }
  static constexpr Fixed max() { return from_raw(max_raw); }
  static constexpr Fixed lowest() { return from_raw(lowest_raw); }
  static constexpr Fixed resolution() { return from_raw(1); }
  // num / den without floating point (den != 0), e.g. a decimal 1234/1000.
  static constexpr Fixed ratio(std::int64_t num, std::int64_t den) { return Fixed(num) / Fixed(den); }

  constexpr std::int64_t raw() const { return raw_; }
  // Truncates toward zero, as a double -> integer cast does.
  template <class I>
    requires(std::is_integral_v<I>)
  explicit constexpr operator I() const {
    const std::int64_t whole = raw_ >= 0 ? raw_ >> frac_bits : -((-raw_) >> frac_bits);
    return static_cast<I>(whole);
  }

  constexpr Fixed operator-() const { return from_raw(-raw_); }  // symmetric range: no overflow
  friend constexpr Fixed operator+(Fixed a, Fixed b) { return from_raw(sat_add(a.raw_, b.raw_)); }
  friend constexpr Fixed operator-(Fixed a, Fixed b) { return from_raw(sat_add(a.raw_, -b.raw_)); }
  friend constexpr Fixed operator*(Fixed a, Fixed b) { return from_raw(mul_raw(a.raw_, b.raw_)); }
  friend constexpr Fixed operator/(Fixed a, Fixed b) { return from_raw(div_raw(a.raw_, b.raw_)); }
  constexpr Fixed& operator+=(Fixed o) { return *this = *this + o; }
  constexpr Fixed& operator-=(Fixed o) { return *this = *this - o; }
  constexpr Fixed& operator*=(Fixed o) { return *this = *this * o; }
  constexpr Fixed& operator/=(Fixed o) { return *this = *this / o; }

  friend constexpr bool operator==(Fixed a, Fixed b) { return a.raw_ == b.raw_; }
  friend constexpr bool operator!=(Fixed a, Fixed b) { return a.raw_ != b.raw_; }
  friend constexpr bool operator<(Fixed a, Fixed b) { return a.raw_ < b.raw_; }
  friend constexpr bool operator>(Fixed a, Fixed b) { return a.raw_ > b.raw_; }
  friend constexpr bool operator<=(Fixed a, Fixed b) { return a.raw_ <= b.raw_; }
  friend constexpr bool operator>=(Fixed a, Fixed b) { return a.raw_ >= b.raw_; }

  // floor(sqrt(v)) to the resolution; negative v gives 0 (as callers clamp).
  static constexpr Fixed sqrt(Fixed v) {
    if (v.raw_ <= 0) return Fixed{};
    if (v.raw_ == max_raw) return max();
    // sqrt(raw * 2^32) is the raw root: raw * 2^32 needs up to 95 bits.
    const auto r = static_cast<std::uint64_t>(v.raw_);
#if defined(__SIZEOF_INT128__) && !defined(KERF_FIXED_PORTABLE)
    if (!std::is_constant_evaluated()) return from_raw(static_cast<std::int64_t>(fixed_detail::isqrt_newton(r)));
#endif
    return from_raw(static_cast<std::int64_t>(fixed_detail::isqrt_128({r >> 32, r << 32})));
  }

 private:
  static constexpr std::int64_t from_integer(std::int64_t v) {
    if (v >= (std::int64_t{1} << 31)) return max_raw;
    if (v < -(std::int64_t{1} << 31)) return lowest_raw;
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(v) << frac_bits);
  }
  static consteval std::int64_t from_double_ct(double v) {
    const double scaled = v * 4294967296.0;
    if (scaled >= 9.2233720368547758e18) return max_raw;
    if (scaled <= -9.2233720368547758e18) return lowest_raw;
    return static_cast<std::int64_t>(scaled < 0 ? scaled - 0.5 : scaled + 0.5);
  }
  static constexpr std::int64_t sat_add(std::int64_t a, std::int64_t b) {
    if (a == max_raw || a == lowest_raw) return a;  // infinity absorbs
    if (b > 0 && a > max_raw - b) return max_raw;
    if (b < 0 && a < lowest_raw - b) return lowest_raw;
    return a + b;
  }
  static constexpr std::uint64_t magnitude(std::int64_t v) {
    return v < 0 ? static_cast<std::uint64_t>(-v) : static_cast<std::uint64_t>(v);
  }
  static constexpr std::int64_t signed_result(std::uint64_t mag, bool negative) {
    if (mag > static_cast<std::uint64_t>(max_raw)) return negative ? lowest_raw : max_raw;
    const auto m = static_cast<std::int64_t>(mag);
    return negative ? -m : m;
  }
  // (a * b) >> 32, rounded to nearest.
  static constexpr std::int64_t mul_raw(std::int64_t a, std::int64_t b) {
    const bool negative = (a < 0) != (b < 0);
#if defined(__SIZEOF_INT128__) && !defined(KERF_FIXED_PORTABLE)
    // 64-bit hosts: the same exact product in one instruction.
    const fixed_detail::Wide w = static_cast<fixed_detail::Wide>(magnitude(a)) * magnitude(b);
    fixed_detail::U128 p{static_cast<std::uint64_t>(w >> 64), static_cast<std::uint64_t>(w)};
#else
    fixed_detail::U128 p = fixed_detail::mul_64x64(magnitude(a), magnitude(b));
#endif
    const std::uint64_t half = std::uint64_t{1} << 31;
    p.lo += half;
    if (p.lo < half) ++p.hi;
    if ((p.hi >> 32) != 0) return negative ? lowest_raw : max_raw;
    return signed_result((p.hi << 32) | (p.lo >> 32), negative);
  }
  // (a << 32) / b, rounded to nearest.
  static constexpr std::int64_t div_raw(std::int64_t a, std::int64_t b) {
    const bool negative = (a < 0) != (b < 0);
    if (b == 0) return a < 0 ? lowest_raw : max_raw;
    const std::uint64_t ua = magnitude(a), ub = magnitude(b);
    // numerator * 2 + 1 over divisor * 2 would overflow; round by the remainder.
    std::uint64_t q = 0;
#if defined(__SIZEOF_INT128__) && !defined(KERF_FIXED_PORTABLE)
    const fixed_detail::Wide wq = (static_cast<fixed_detail::Wide>(ua) << 32) / ub;
    if ((wq >> 64) != 0) return negative ? lowest_raw : max_raw;
    q = static_cast<std::uint64_t>(wq);
#else
    if ((ua >> 31) == 0) {
      q = (ua << 32) / ub;  // the numerator fits 64 bits: the target's own division
    } else if (!fixed_detail::div_128_64({ua >> 32, ua << 32}, ub, q)) {
      return negative ? lowest_raw : max_raw;
    }
#endif
    const std::uint64_t rem = (ua << 32) - q * ub;  // < ub: the low 64 bits suffice
    if (rem >= ub - rem && q != UINT64_MAX) ++q;      // rem >= ub / 2
    return signed_result(q, negative);
  }

  std::int64_t raw_ = 0;
};

// The fixed-point trigonometry the vertex fitter and the interpolator use
// (fixed_trig.hpp: CORDIC on the raw values).
namespace fixed_trig {
Fixed atan2(Fixed y, Fixed x);
Fixed sin(Fixed a);
Fixed cos(Fixed a);
}  // namespace fixed_trig

template <>
struct Scalar<Fixed> {
  static constexpr Fixed zero() { return Fixed{}; }
  static constexpr Fixed one() { return Fixed(1); }
  static constexpr Fixed pi() { return Fixed::from_raw(13493037705); }  // pi * 2^32
  static constexpr Fixed from_int(long v) { return Fixed(v); }
  static constexpr Fixed sqrt(Fixed v) { return Fixed::sqrt(v); }
  static constexpr Fixed abs(Fixed v) { return v < Fixed{} ? -v : v; }
  static Fixed atan2(Fixed y, Fixed x) { return fixed_trig::atan2(y, x); }
  // asin(v) = atan2(v, sqrt(1 - v^2)), |v| <= 1.
  static Fixed asin(Fixed v) {
    const Fixed c = Fixed::sqrt(Fixed(1) - v * v);
    return fixed_trig::atan2(v, c);
  }
  static Fixed cos(Fixed v) { return fixed_trig::cos(v); }
  static Fixed sin(Fixed v) { return fixed_trig::sin(v); }
  // The saturated ends stand for +-infinity.
  static constexpr bool is_finite(Fixed v) { return v != Fixed::max() && v != Fixed::lowest(); }
  // One step of the resolution relative to 1: the scaled fitter works near 1.
  static constexpr Fixed epsilon() { return Fixed::resolution(); }
  static constexpr Fixed infinity() { return Fixed::max(); }
  // The power of two that brings v (> 0) into [0.5, 1): the fitter's scaled
  // problem then never squares anything above 8.
  // The power of two a short chord's local terms are scaled by before they are
  // squared (fit/detail/chord.hpp): Q31.32 has an absolute resolution, so a
  // square of 1e-5 would keep 7 bits and one of 1e-8 none.
  static constexpr Fixed local_scale(Fixed m) { return m > Fixed{} ? normaliser(m) : Fixed(1); }
  static constexpr Fixed normaliser(Fixed v) {
    const int lz = fixed_detail::leading_zeros(static_cast<std::uint64_t>(v.raw()));
    // v.raw() has its top bit at 63 - lz; we want it at frac_bits - 1.
    const int shift = (63 - lz) - (Fixed::frac_bits - 1);  // divide by 2^shift
    const int target = Fixed::frac_bits - shift;           // raw exponent of the factor
    if (target >= 63) return Fixed::max();
    if (target < 0) return Fixed::resolution();
    return Fixed::from_raw(std::int64_t{1} << target);
  }
};

}  // namespace kerf
