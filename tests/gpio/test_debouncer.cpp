// hal::Debouncer: times are binary fractions so that "exactly debounce_s"
// is exact in floating point.
#include "kerf/hal/debouncer.hpp"

#include <gtest/gtest.h>

namespace kerf::hal {
namespace {

TEST(Debouncer, FirstSampleIsTakenAsIs) {
  Debouncer high(0.5, false);
  EXPECT_TRUE(high.update(true, 10.0));
  Debouncer low(0.5, false);
  EXPECT_FALSE(low.update(false, 10.0));
}

TEST(Debouncer, BounceShorterThanDebounceIsIgnored) {
  Debouncer d(0.25, false);
  EXPECT_FALSE(d.update(false, 0.0));
  // Bounces of up to 0.1875 s, each ended by a sample back at the old value.
  EXPECT_FALSE(d.update(true, 1.0));
  EXPECT_FALSE(d.update(true, 1.125));
  EXPECT_FALSE(d.update(false, 1.1875));
  EXPECT_FALSE(d.update(true, 1.25));
  EXPECT_FALSE(d.update(true, 1.4375));  // 0.1875 s into this bounce
  EXPECT_FALSE(d.update(false, 1.5));
  // Each return to the old value restarts the wait: true again from 1.5625
  // is only 0.1875 s old at 1.75, though 1.25 is 0.5 s back.
  EXPECT_FALSE(d.update(true, 1.5625));
  EXPECT_FALSE(d.update(true, 1.75));
  EXPECT_TRUE(d.update(true, 1.8125));  // held 0.25 s at last
}

TEST(Debouncer, HeldChangeIsTakenAfterExactlyDebounce) {
  Debouncer d(0.25, false);
  EXPECT_FALSE(d.update(false, 0.0));
  EXPECT_FALSE(d.update(true, 2.0));
  EXPECT_FALSE(d.update(true, 2.125));
  EXPECT_FALSE(d.update(true, 2.2421875));  // just short of 0.25 s
  EXPECT_TRUE(d.update(true, 2.25));        // exactly 0.25 s
  // And back: the release is debounced the same way.
  EXPECT_TRUE(d.update(false, 3.0));
  EXPECT_TRUE(d.update(false, 3.1875));
  EXPECT_FALSE(d.update(false, 3.25));
}

TEST(Debouncer, ZeroDebounceFollowsEverySample) {
  Debouncer d(0.0, false);
  EXPECT_FALSE(d.update(false, 0.0));
  EXPECT_TRUE(d.update(true, 0.0));
  EXPECT_FALSE(d.update(false, 0.001));
  // A negative debounce is treated as none rather than as "never".
  Debouncer n(-1.0, false);
  EXPECT_FALSE(n.update(false, 0.0));
  EXPECT_TRUE(n.update(true, 0.5));
}

TEST(Debouncer, ActiveLowInvertsBeforeDebouncing) {
  Debouncer d(0.25, true);
  EXPECT_TRUE(d.update(false, 0.0));   // pin low = asserted
  EXPECT_TRUE(d.update(true, 1.0));    // pin released, not yet held
  EXPECT_FALSE(d.update(true, 1.25));  // held 0.25 s: released
  EXPECT_FALSE(d.update(false, 2.0));
  EXPECT_TRUE(d.update(false, 2.5));
}

TEST(Debouncer, ResetTakesTheNextSampleAsIs) {
  Debouncer d(1.0, false);
  EXPECT_FALSE(d.update(false, 0.0));
  EXPECT_FALSE(d.update(true, 0.5));
  d.reset();
  EXPECT_TRUE(d.update(true, 0.5));
}

}  // namespace
}  // namespace kerf::hal
