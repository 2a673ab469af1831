// The band search's start regions (fit/band/start_region.hpp): a quick
// "yes" for pair i -> j that spares the pair test. A yes must never be a
// pair the pair test refuses (the search's verdicts, and so every fit, stay
// what they were), and it must say yes to most pairs that fit, or it spares
// nothing. Checked pair by pair, in the order the search asks (one start,
// j growing), on the test curves, a jittered circle, a zigzag and corpus
// polylines (tests/support/bridge/start_region_check.hpp).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "band_pair_inputs.hpp"
#include "bridge/start_region_check.hpp"
#include "typed_core_helpers.hpp"

namespace {

using VD = kerf::Vec2<double>;
using kerf::fit::BandWidth;
using kerf_test::StartRegionTally;

constexpr std::uint32_t kSpan = 80;

void expect_sound(const std::vector<VD>& p, BandWidth<double> w, const std::string& what, StartRegionTally& t) {
  ASSERT_TRUE(kerf_test::start_regions_sound(p, std::vector<BandWidth<double>>(p.size(), w), kSpan, t))
      << what << ": " << t.wrong;
}

void expect_most_admitted(const StartRegionTally& t, const std::string& what) {
  EXPECT_GT(t.valid, 0u) << what;
  EXPECT_GE(static_cast<double>(t.admitted), 0.8 * static_cast<double>(t.valid))
      << what << ": admitted " << t.admitted << " of " << t.valid << " valid pairs";
}

TEST(BandStartRegion, NoFalseYesAndMostAdmittedOnTheTestCurves) {
  for (const char* curve : {"parabola.txt", "circle.txt", "ellipse.txt", "sine.txt", "spiral.txt"}) {
    const std::vector<VD> p = kerf::test::load_curve(curve);
    ASSERT_GT(p.size(), 2u) << curve;
    StartRegionTally t;
    for (double tol : {0.005, 0.02, 0.1}) expect_sound(p, {tol, tol}, curve, t);
    expect_most_admitted(t, curve);
    // One-sided and unequal widths: only soundness (fewer pairs fit).
    StartRegionTally one_sided;
    expect_sound(p, {0.0, 0.02}, std::string(curve) + " right side only", one_sided);
    expect_sound(p, {0.02 / 3, 0.02}, std::string(curve) + " unequal sides", one_sided);
  }
}

TEST(BandStartRegion, NoFalseYesOnAJitteredCircleAndAZigzag) {
  StartRegionTally a, b;
  expect_sound(kerf::test::jittered_circle(2511), {0.01, 0.01}, "jittered circle", a);
  expect_sound(kerf::test::zigzag(), {0.1, 0.1}, "zigzag", b);
  expect_most_admitted(a, "jittered circle");
}

TEST(BandStartRegion, NoFalseYesAndMostAdmittedOnCorpusPolylines) {
  const std::vector<std::vector<VD>> lines = kerf::test::tball_pocket_polylines(4);
  ASSERT_EQ(lines.size(), 4u);
  StartRegionTally t;
  for (std::size_t k = 0; k < lines.size(); ++k)
    expect_sound(lines[k], {0.025, 0.025}, "tball-pocket polyline " + std::to_string(k + 1), t);
  expect_most_admitted(t, "tball-pocket");
}

}  // namespace
