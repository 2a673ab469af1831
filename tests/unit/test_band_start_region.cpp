// The band search's start regions (fit/band/start_region.hpp): a quick
// "yes" for pair i -> j that spares the pair test. A yes must never be a
// pair the pair test refuses (the search's verdicts, and so every fit, stay
// what they were), and it must say yes to most pairs that fit, or it spares
// nothing. Checked pair by pair, in the order the search asks (one start,
// j growing), on the test curves, a jittered circle, a zigzag and corpus
// polylines (tests/support/bridge/start_region_check.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "bridge/start_region_check.hpp"
#include "job/gcode_reader.hpp"
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
  std::vector<VD> jitter, zigzag;
  std::uint32_t seed = 2511;
  auto noise = [&] {
    seed = seed * 1664525u + 1013904223u;
    return static_cast<double>(seed >> 8) / 16777216.0 - 0.5;
  };
  for (int k = 0; k < 300; ++k) {
    const double t = 0.02 * k;
    jitter.push_back({10 * std::cos(t) + 0.004 * noise(), 10 * std::sin(t) + 0.004 * noise()});
    zigzag.push_back({0.3 * k, (k % 4 < 2 ? 0.05 : -0.05) * (1 + (k % 7))});
  }
  StartRegionTally a, b;
  expect_sound(jitter, {0.01, 0.01}, "jittered circle", a);
  expect_sound(zigzag, {0.1, 0.1}, "zigzag", b);
  expect_most_admitted(a, "jittered circle");
}

TEST(BandStartRegion, NoFalseYesAndMostAdmittedOnCorpusPolylines) {
  const kerf::job::GcodeFile g =
      kerf::job::read_gcode(std::string(KERF_TEST_DATA_DIR) + "/gcode/cncjs_tball-pocket.gcode");
  ASSERT_TRUE(g.ok) << g.line << ": " << g.reason;
  StartRegionTally t;
  std::size_t taken = 0;
  for (std::size_t k = 0; k < g.polylines.size() && taken < 4; ++k) {
    std::vector<VD> p;
    for (const VD& v : g.polylines[k].points)
      if (p.empty() || !(p.back() == v)) p.push_back(v);
    if (p.size() < 40) continue;
    if (p.size() > 400) p.resize(400);
    ++taken;
    expect_sound(p, {0.025, 0.025}, "tball-pocket polyline " + std::to_string(k + 1), t);
  }
  EXPECT_EQ(taken, 4u);
  expect_most_admitted(t, "tball-pocket");
}

}  // namespace
