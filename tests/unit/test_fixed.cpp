// kerf::Fixed against double: every operation, its rounding, and what it does
// at the edges of its range (saturation stands for infinity).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "kerf/core/fixed.hpp"
#include "kerf/core/fixed_convert.hpp"

namespace {

using kerf::Fixed;
using Sc = kerf::Scalar<Fixed>;
constexpr double q = kerf::fixed_quantum;

double d(Fixed v) { return kerf::to_double(v); }
Fixed f(double v) { return kerf::fixed_from_double(v); }

TEST(Fixed, IntegersAndLiteralsAreExact) {
  EXPECT_EQ(Fixed(3).raw(), std::int64_t{3} << 32);
  EXPECT_EQ(Fixed(-7).raw(), -(std::int64_t{7} << 32));
  constexpr Fixed half = Fixed(0.5);  // consteval: converted by the compiler
  EXPECT_EQ(half.raw(), std::int64_t{1} << 31);
  EXPECT_EQ(Fixed(1e-9).raw(), 4);  // 4.29 steps, rounded
  EXPECT_EQ(static_cast<long>(Fixed(-2.75)), -2);  // truncates like a double cast
  EXPECT_EQ(static_cast<long>(Fixed(2.75)), 2);
}

TEST(Fixed, CoversTenMetresAtOneMicrometre) {
  // +-1e4 mm at 1e-3 mm: both ends and one micrometre steps are distinct.
  const Fixed top = Fixed::ratio(10000001, 1000);
  const Fixed next = Fixed::ratio(10000000, 1000);
  EXPECT_NEAR(d(top), 10000.001, q);
  EXPECT_NEAR(d(top - next), 0.001, 2 * q);
  EXPECT_NEAR(d(-top), -10000.001, q);
  // The squared diagonal of a 20 m x 20 m part fits: no intermediate overflows.
  const Fixed span = Fixed(20000);
  const Fixed sq = span * span + span * span;
  EXPECT_TRUE(Sc::is_finite(sq));
  EXPECT_NEAR(d(sq), 8e8, q);
  EXPECT_NEAR(d(Sc::sqrt(sq)), std::sqrt(8e8), 1e-6);
}

TEST(Fixed, ArithmeticMatchesDoubleWithinOneStep) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-30000.0, 30000.0);
  for (int k = 0; k < 20000; ++k) {
    const Fixed a = f(u(rng)), b = f(u(rng) / 1000.0);
    const double da = d(a), db = d(b);
    EXPECT_EQ(d(a + b), da + db);
    EXPECT_EQ(d(a - b), da - db);
    EXPECT_NEAR(d(a * b), da * db, 0.5 * q + std::abs(da * db) * 1e-15);
    if (db != 0.0 && std::abs(da / db) < 2e9) {
      EXPECT_NEAR(d(a / b), da / db, 0.5 * q + std::abs(da / db) * 1e-15);
    }
  }
}

TEST(Fixed, SmallValuesKeepFullResolution) {
  const Fixed tiny = Fixed::resolution();
  EXPECT_EQ((tiny * Fixed(3)).raw(), 3);
  EXPECT_EQ((Fixed(3) * tiny).raw(), 3);
  EXPECT_EQ((tiny / Fixed(2)).raw(), 1);  // 0.5 step rounds half up
  EXPECT_EQ((Fixed::ratio(1, 3) * Fixed(3)).raw(), Fixed(1).raw() - 1);  // 1/3 rounds down
  EXPECT_EQ((Fixed(-1) / Fixed(3)).raw(), -Fixed::ratio(1, 3).raw());   // symmetric rounding
}

TEST(Fixed, SquareRootIsTheFloorOfTheTrueRoot) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 2e9);
  for (int k = 0; k < 5000; ++k) {
    const double v = k % 2 ? u(rng) : u(rng) * 1e-9;
    const Fixed r = Sc::sqrt(f(v));
    const double want = std::sqrt(d(f(v)));
    EXPECT_LE(d(r), want + 1e-6 * q * want);
    EXPECT_GT(d(r) + q, want - 1e-15 * want);
  }
  EXPECT_EQ(Sc::sqrt(Fixed(4)).raw(), Fixed(2).raw());
  EXPECT_EQ(Sc::sqrt(Fixed::resolution()).raw(), std::int64_t{1} << 16);
  EXPECT_EQ(Sc::sqrt(Fixed(-4)).raw(), 0);
  EXPECT_EQ(Sc::sqrt(Fixed::max()), Fixed::max());  // infinity stays infinite
}

TEST(Fixed, OverflowSaturatesToInfinity) {
  const Fixed big = Fixed(2000000000);
  EXPECT_EQ(big * big, Fixed::max());
  EXPECT_EQ(big * -big, Fixed::lowest());
  EXPECT_EQ(big + big, Fixed::max());
  EXPECT_EQ(-big - big, Fixed::lowest());
  EXPECT_EQ(Fixed(1) / Fixed(0), Fixed::max());
  EXPECT_EQ(Fixed(-1) / Fixed(0), Fixed::lowest());
  EXPECT_EQ(big / Fixed::resolution(), Fixed::max());
  EXPECT_EQ(Fixed(5000000000LL), Fixed::max());  // out-of-range integer
  EXPECT_FALSE(Sc::is_finite(big * big));
  EXPECT_FALSE(Sc::is_finite(Sc::infinity()));
  EXPECT_TRUE(Sc::is_finite(big));
  // Infinity absorbs finite additions, as in double.
  EXPECT_EQ(Sc::infinity() - Fixed(1), Sc::infinity());
  EXPECT_TRUE(Fixed(1e9) < Sc::infinity());
}

TEST(Fixed, ComparisonsAndAbs) {
  EXPECT_TRUE(Fixed(-1) < Fixed(0));
  EXPECT_TRUE(Fixed::resolution() > Fixed(0));
  EXPECT_TRUE(Fixed(2) >= Fixed(2));
  EXPECT_TRUE(Fixed(2) <= Fixed(2));
  EXPECT_TRUE(Fixed(2) != Fixed(3));
  EXPECT_EQ(Sc::abs(Fixed(-3)), Fixed(3));
  EXPECT_EQ(Sc::abs(Fixed::lowest()), Fixed::max());
}

TEST(Fixed, TrigonometryMatchesDouble) {
  for (double a = -20.0; a <= 20.0; a += 0.0137) {
    EXPECT_NEAR(d(Sc::sin(f(a))), std::sin(d(f(a))), 4 * q) << a;
    EXPECT_NEAR(d(Sc::cos(f(a))), std::cos(d(f(a))), 4 * q) << a;
  }
  for (double a = -3.14; a <= 3.14; a += 0.01) {
    for (double r : {1e-6, 1.0, 1e5}) {
      const Fixed x = f(r * std::cos(a)), y = f(r * std::sin(a));
      EXPECT_NEAR(d(Sc::atan2(y, x)), std::atan2(d(y), d(x)), 4 * q + 2 * q / r) << a << " " << r;
    }
  }
  EXPECT_NEAR(d(Sc::atan2(Fixed(0), Fixed(-1))), M_PI, 4 * q);
  EXPECT_NEAR(d(Sc::atan2(Fixed(-1), Fixed(0))), -M_PI / 2, 4 * q);
  EXPECT_EQ(Sc::atan2(Fixed(0), Fixed(0)), Fixed(0));
  for (double v = -1.0; v <= 1.0; v += 0.01)
    EXPECT_NEAR(d(Sc::asin(f(v))), std::asin(d(f(v))), 1e-4 * (1.0 - std::abs(v) < 1e-3) + 20 * q)
        << v;
  EXPECT_NEAR(d(Sc::pi()), M_PI, q);
}

TEST(Fixed, NormaliserBringsValuesIntoHalfToOne) {
  for (double v : {1e-9, 3e-5, 0.5, 0.75, 1.0, 3.0, 1234.5, 1e9}) {
    const Fixed n = Sc::normaliser(f(v));
    const double s = d(f(v) * n);
    EXPECT_GE(s, 0.5) << v;
    EXPECT_LT(s, 1.0) << v;
    // a power of two: scaling is exact
    EXPECT_EQ(n.raw() & (n.raw() - 1), 0) << v;
  }
}

// The portable 32-bit-limb routines (what Cortex-M runs) against the host's
// 128-bit arithmetic, which the host build uses for speed. 32-bit hosts
// (armhf) have no 128-bit type: they run the portable routines everywhere,
// and the fixed-point results of the other tests check them there.
#if defined(__SIZEOF_INT128__) && !defined(KERF_FIXED_PORTABLE)
TEST(FixedPortable, LimbRoutinesMatchTheHostsWideArithmetic) {
  namespace fd = kerf::fixed_detail;
  using U = fd::Wide;
  std::mt19937_64 rng(17);
  for (int k = 0; k < 200000; ++k) {
    const std::uint64_t a = rng() >> (rng() % 64), b = rng() >> (rng() % 64);
    const fd::U128 p = fd::mul_64x64(a, b);
    const U w = static_cast<U>(a) * b;
    ASSERT_EQ(p.hi, static_cast<std::uint64_t>(w >> 64));
    ASSERT_EQ(p.lo, static_cast<std::uint64_t>(w));
    if (b != 0) {
      std::uint64_t quot = 0;
      const U n = static_cast<U>(a) << 32;
      const bool fits = fd::div_128_64({a >> 32, a << 32}, b, quot);
      ASSERT_EQ(fits, (n / b) >> 64 == 0);
      if (fits) {
        ASSERT_EQ(quot, static_cast<std::uint64_t>(n / b));
      }
    }
    const std::uint64_t r = a >> 1;  // raw values are non-negative int64
    ASSERT_EQ(fd::isqrt_128({r >> 32, r << 32}), fd::isqrt_newton(r)) << r;
  }
  EXPECT_EQ(fd::isqrt_128({0, 0}), 0u);
  EXPECT_EQ(fd::isqrt_newton(1), 65536u);
}
#endif

}  // namespace
