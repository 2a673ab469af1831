// The band pair test skips snapping chain points to the piece's ends when a
// cached chain's bounding box is far from both (band_pair.hpp, apart()), and
// then tries the chain's slab first (band_slab.hpp); without a chain cache
// every point is snapped and every chain condition taken. The two must make
// the same decisions: the same pieces, bit for bit, on the test curves and
// the G-code corpus, with symmetric and one-sided widths (a side of width 0
// or below the coordinates' resolution is where snapping matters). Pair by
// pair, and the cells visited in another order: test_band_pair_shortcuts.cpp.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "io/band_storage.hpp"
#include "job/gcode_reader.hpp"
#include "kerf/fit/band.hpp"
#include "typed_core_helpers.hpp"

namespace {

using VD = kerf::Vec2<double>;

std::vector<kerf::fit::Piece<double>> fit(const std::vector<VD>& p, kerf::fit::BandWidth<double> width,
                                          bool cache, std::size_t& cells_cached) {
  const std::size_t n = p.size();
  std::vector<kerf::fit::BandWidth<double>> w(n, width);
  kerf::io::BandStorage storage(n);
  kerf::fit::BandWorkspace<double> ws = storage.workspace();
  if (!cache) ws.chains = {};
  std::vector<kerf::fit::Piece<double>> out(n);
  const auto r = kerf::fit::fit_band_min_count<double>({p.data(), n}, {w.data(), n}, ws, {out.data(), n});
  EXPECT_TRUE(r.ok());
  for (const auto& slot : ws.chains) cells_cached += slot.key != 0 ? 1 : 0;
  out.resize(r.ok() ? r.value().pieces : 0);
  return out;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same(const std::vector<VD>& p, double tol, const std::string& what) {
  const kerf::fit::BandWidth<double> widths[] = {{tol, tol}, {0.0, tol}, {tol, 0.0}, {tol * 1e-14, tol}};
  for (const kerf::fit::BandWidth<double>& w : widths) {
    std::size_t cached = 0, none = 0;
    const auto with = fit(p, w, true, cached);
    const auto without = fit(p, w, false, none);
    const std::string at = what + " widths " + std::to_string(w.left) + "/" + std::to_string(w.right);
    EXPECT_GT(cached, 0u) << at;  // the fast path was there to be taken
    ASSERT_EQ(with.size(), without.size()) << at;
    for (std::size_t k = 0; k < with.size(); ++k) {
      const auto& a = with[k].segment;
      const auto& b = without[k].segment;
      EXPECT_EQ(with[k].first, without[k].first) << at << " piece " << k;
      EXPECT_EQ(with[k].last, without[k].last) << at << " piece " << k;
      EXPECT_EQ(a.dir, b.dir) << at << " piece " << k;
      EXPECT_TRUE(same_bits(a.centre.x, b.centre.x) && same_bits(a.centre.y, b.centre.y)) << at << " piece " << k;
      EXPECT_TRUE(same_bits(with[k].error, without[k].error)) << at << " piece " << k;
    }
  }
}

TEST(BandChainCache, SamePiecesWithAndWithoutOnTheTestCurves) {
  for (const char* curve : {"parabola.txt", "circle.txt", "ellipse.txt", "sine.txt", "spiral.txt"}) {
    const std::vector<VD> p = kerf::test::load_curve(curve);
    ASSERT_GT(p.size(), 2u) << curve;
    for (double tol : {0.01, 0.05, 0.2}) expect_same(p, tol, std::string(curve) + " tol " + std::to_string(tol));
  }
}

TEST(BandChainCache, SamePiecesWithAndWithoutOnTheGcodeCorpus) {
  for (const char* name : {"cncjs_jsdc-laser.gcode", "cncjs_tball-engrave.gcode"}) {
    const kerf::job::GcodeFile g = kerf::job::read_gcode(std::string(KERF_TEST_DATA_DIR) + "/gcode/" + name);
    ASSERT_TRUE(g.ok) << name << ":" << g.line << ": " << g.reason;
    for (std::size_t k = 0; k < g.polylines.size(); ++k) {
      std::vector<VD> p;
      for (const VD& v : g.polylines[k].points)
        if (p.empty() || !(p.back() == v)) p.push_back(v);
      if (p.size() < 3) continue;
      expect_same(p, 0.025, std::string(name) + " polyline " + std::to_string(k + 1));
    }
  }
}

}  // namespace
