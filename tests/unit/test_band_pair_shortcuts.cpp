// The band pair test takes two shortcuts when the region caches its chains
// (band_pair.hpp): the slab test, which passes a cell whose chain lies
// clear of the arc's disc at both ends of the range, and the cells that
// bound the last test of a start, visited first. Both only skip work, so
// every pair must get the verdict that the full conditions give without a
// cache, and the same range: bit for bit with the slab test; with the cells
// visited in another order, to rounding (a segment's condition is skipped
// when clear at the range's ends, and where a root's cut lands within
// rounding of an end, whether it is applied depends on the range then).
// Checked pair by pair, both ways round, on the test curves, a jittered and
// a zigzag path and corpus polylines, with symmetric and one-sided widths;
// and, where no barrier lies between the ends, with the search's promise of
// that (set_clear_between), bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "band_pair_inputs.hpp"
#include "io/band_storage.hpp"
#include "kerf/fit/band.hpp"
#include "kerf/fit/band/pair.hpp"
#include "typed_core_helpers.hpp"

namespace {

using VD = kerf::Vec2<double>;
using kerf::fit::BandPair;
using kerf::fit::BandRegion;
using kerf::fit::BandWidth;
using kerf::fit::PsiRange;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Pseudo-angles lie in [0, 2]: a few ulps of 2.
constexpr double kRounding = 1e-13;

struct Tally {
  std::size_t pairs = 0;
  std::size_t valid = 0;
  std::size_t clear = 0;  // pairs also tested as the search knows them to be barrier-free
};

// Every pair i -> j with j - i <= span, in the order a search asks them.
void expect_same_verdicts(const std::vector<VD>& p, BandWidth<double> width, const std::string& what,
                          Tally& tally) {
  const std::size_t n = p.size();
  const std::vector<BandWidth<double>> w(n, width);
  kerf::io::BandStorage storage(n);
  const kerf::fit::BandWorkspace<double> ws = storage.workspace();
  const auto built = kerf::fit::band_region<double>({p.data(), n}, {w.data(), n}, ws);
  ASSERT_TRUE(built.ok()) << what;
  const BandRegion<double> plain = built.value();
  BandRegion<double> cached = plain;
  cached.cache_chains(ws.chains);
  ASSERT_FALSE(ws.chains.empty()) << what;
  constexpr std::uint32_t kSpan = 48;
  const auto last = static_cast<std::uint32_t>(n - 1);
  for (std::uint32_t i = 0; i < last; ++i) {
    for (const int orient : {1, -1}) {
      // As the search keeps it for one start.
      std::uint32_t binding[2] = {BandPair<double>::kNoCell, BandPair<double>::kNoCell};
      for (std::uint32_t j = i + 1; j <= last && j - i <= kSpan; ++j) {
        PsiRange<double> full, slab, bound;
        std::uint32_t fail_full = 0, fail_slab = 0, fail_bound = 0;
        const bool ok_full = BandPair<double>(plain, i, j, orient).run(full, fail_full);
        const bool ok_slab = BandPair<double>(cached, i, j, orient).run(slab, fail_slab);
        const bool ok_bound = BandPair<double>(cached, i, j, orient).run(bound, fail_bound, binding);
        // The search's own view: no barrier look-up per cell when none lies
        // between the ends (it knows from its table).
        bool barrier = false;
        for (std::uint32_t k = i + 1; k < j; ++k) barrier = barrier || cached.vertex(k).barrier;
        if (!barrier) {
          BandPair<double> told(cached, i, j, orient);
          told.set_clear_between();
          PsiRange<double> clear;
          std::uint32_t fail_clear = 0;
          ASSERT_EQ(told.run(clear, fail_clear), ok_slab) << what << " pair " << i << "->" << j;
          if (ok_slab) {
            EXPECT_TRUE(same_bits(clear.lo, slab.lo) && same_bits(clear.hi, slab.hi)) << what;
          }
          ++tally.clear;
        }
        const std::string at = what + " pair " + std::to_string(i) + "->" + std::to_string(j) +
                               (orient > 0 ? " ccw" : " cw");
        ++tally.pairs;
        ASSERT_EQ(ok_full, ok_slab) << at;
        ASSERT_EQ(ok_full, ok_bound) << at;
        if (!ok_full) continue;
        ++tally.valid;
        EXPECT_TRUE(same_bits(full.lo, slab.lo) && same_bits(full.hi, slab.hi))
            << at << ": [" << full.lo << ", " << full.hi << "] vs slab [" << slab.lo << ", " << slab.hi << "]";
        EXPECT_NEAR(full.lo, bound.lo, kRounding) << at;
        EXPECT_NEAR(full.hi, bound.hi, kRounding) << at;
      }
    }
  }
}

void check_widths(const std::vector<VD>& p, double tol, const std::string& what, Tally& tally) {
  const BandWidth<double> widths[] = {{tol, tol}, {0.0, tol}, {tol, 0.0}, {tol / 3, tol}};
  for (const BandWidth<double>& w : widths)
    expect_same_verdicts(p, w, what + " widths " + std::to_string(w.left) + "/" + std::to_string(w.right),
                         tally);
}

TEST(BandPairShortcuts, SameVerdictsAndRangesOnTheTestCurves) {
  Tally tally;
  for (const char* curve : {"parabola.txt", "circle.txt", "ellipse.txt", "sine.txt", "spiral.txt"}) {
    const std::vector<VD> p = kerf::test::load_curve(curve);
    ASSERT_GT(p.size(), 2u) << curve;
    for (double tol : {0.01, 0.05}) check_widths(p, tol, std::string(curve) + " tol " + std::to_string(tol), tally);
  }
  // Many pairs fit: the shortcuts had work to skip.
  EXPECT_GT(tally.valid, tally.pairs / 10) << tally.valid << " of " << tally.pairs;
  EXPECT_GT(tally.clear, tally.pairs / 2) << tally.clear << " of " << tally.pairs;
}

TEST(BandPairShortcuts, SameVerdictsAndRangesOnJitterAndZigzags) {
  Tally tally;
  check_widths(kerf::test::jittered_circle(12345), 0.01, "jittered circle", tally);
  check_widths(kerf::test::zigzag(), 0.1, "zigzag", tally);
  EXPECT_GT(tally.valid, 0u);
}

TEST(BandPairShortcuts, SameVerdictsAndRangesOnCorpusPolylines) {
  Tally tally;
  const std::vector<std::vector<VD>> lines = kerf::test::tball_pocket_polylines(4);
  ASSERT_EQ(lines.size(), 4u);
  for (std::size_t k = 0; k < lines.size(); ++k)
    expect_same_verdicts(lines[k], {0.025, 0.025}, "tball-pocket polyline " + std::to_string(k + 1), tally);
  EXPECT_GT(tally.valid, tally.pairs / 10) << tally.valid << " of " << tally.pairs;
}

// Issue 25: a jump, then 17 exactly collinear steps, with per-vertex widths
// (tests/fuzz/corpus/fit_band/collinear_run_order, from fuzz_fit_band). At
// the tie-break's shortcut scale (widths times 1e-12, gates of 1e-17 on
// coordinates near 1) a segment's binding point was rebuilt as coordinates
// that rounded across the chord and cut the line away, in some cell orders
// only: the search accepted 1 -> 18 and choose() refused it. Every pair must
// get one verdict in every order, and the fit must exist (the line is in the
// band).
TEST(BandPairShortcuts, CollinearRunWithPerVertexWidthsHasOneVerdictInEveryOrder) {
  struct Row {
    double x, y, w;
  };
  const Row rows[] = {
      {9920, 9920, 141.875},
      {-45248, -45248, 141.875},
      {-45440, -46336, 299.7109375},
      {-45632, -47424, 299.7109375},
      {-45824, -48512, 299.7109375},
      {-46016, -49600, 299.7109375},
      {-46208, -50688, 299.7109375},
      {-46400, -51776, 299.7109375},
      {-46592, -52864, 299.7109375},
      {-46784, -53952, 177.34375},
      {-46976, -55040, 1.7734375},
      {-47168, -56128, 1.7734375},
      {-47360, -57216, 1.7734375},
      {-47552, -58304, 1.7734375},
      {-47744, -59392, 1.7734375},
      {-47936, -60480, 1.7734375},
      {-48128, -61568, 1.7734375},
      {-48320, -62656, 143.6484375},
      {-48512, -63744, 1.7734375}};
  std::vector<VD> p;
  std::vector<BandWidth<double>> w;
  for (const Row& r : rows) {
    p.push_back({r.x, r.y});
    w.push_back({r.w, r.w});
  }
  const std::size_t n = p.size();
  std::mt19937 rng(25);
  std::size_t orders = 0;
  for (const double scale : {1.0, 1e-12}) {
    std::vector<BandWidth<double>> ws_w = w;
    for (BandWidth<double>& b : ws_w) b = {b.left * scale, b.right * scale};
    kerf::io::BandStorage storage(n);
    const auto built = kerf::fit::band_region<double>({p.data(), n}, {ws_w.data(), n}, storage.workspace());
    ASSERT_TRUE(built.ok());
    const BandRegion<double> region = built.value();
    for (std::uint32_t i = 0; i + 2 < n; ++i)
      for (std::uint32_t j = i + 2; j < n; ++j)
        for (const int orient : {1, -1}) {
          const BandPair<double> pair(region, i, j, orient);
          PsiRange<double> range;
          std::uint32_t fail = 0;
          const bool want = pair.run(range, fail);
          std::vector<std::uint32_t> cells;
          for (std::uint32_t k = i; k < j; ++k) cells.push_back(k);
          for (int t = 0; t < 12; ++t, ++orders) {
            if (t == 0) std::reverse(cells.begin(), cells.end());
            else std::shuffle(cells.begin(), cells.end(), rng);
            PsiRange<double> r;
            bool ok = pair.ends(r);
            for (std::uint32_t k : cells) ok = ok && pair.cell(k, r);
            ASSERT_EQ(ok, want) << "scale " << scale << " pair " << i << "->" << j << (orient > 0 ? " ccw" : " cw")
                                << " order " << t;
          }
        }
  }
  EXPECT_GT(orders, 0u);
  kerf::io::BandStorage storage(n);
  std::vector<kerf::fit::Piece<double>> out(n);
  const auto fit = kerf::fit::fit_band_min_count<double>({p.data(), n}, {w.data(), n}, storage.workspace(),
                                                         {out.data(), n});
  ASSERT_TRUE(fit.ok()) << kerf::to_string(fit.status());
  EXPECT_EQ(fit.value().pieces, 2u);  // the jump, then the line
}

}  // namespace
