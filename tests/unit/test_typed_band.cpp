// The band fitter in both scalar types (the typed core suite's band part):
// on every test curve and on the cut paths of the G-code corpus, the
// fixed-point fitter must find the same piece counts as double, and every
// fixed-point piece must lie inside the band, proven in double by the
// independent referee (tests/support/band_checker.hpp), within the
// documented quantization.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "band_checker.hpp"
#include "job/gcode_reader.hpp"
#include "kerf/fit/band.hpp"
#include "typed_core_helpers.hpp"

namespace {

using kerf::Fixed;
using kerf::test::from_d;
using kerf::test::to_d;
using VD = kerf::Vec2<double>;

template <class S>
class TypedBand : public ::testing::Test {};
using Scalars = ::testing::Types<double, Fixed>;
TYPED_TEST_SUITE(TypedBand, Scalars);

// What a piece may leave the band by: nothing beyond double's rounding for
// double; for Fixed the quantization kerf documents for fixed-point pieces
// (job/fit_fixed.hpp): 64 steps of 2^-32 of the power of two above the
// largest coordinate, the resolution of the scaled problem the fitter solves.
template <class S>
double allowance(const std::vector<VD>& pts) {
  double big = 1.0;
  for (const VD& p : pts) big = std::max({big, std::abs(p.x), std::abs(p.y)});
  if constexpr (__is_same(S, Fixed)) return 64 * kerf::fixed_quantum * std::exp2(std::ceil(std::log2(big)));
  else return 1e-9 * big;
}

// Band storage for n points in vectors (the tests may allocate).
template <class S>
struct BandBuffers {
  explicit BandBuffers(std::size_t n)
      : words(kerf::fit::band_workspace_words(n)), points(n), vertices(n), pieces(n) {}
  kerf::fit::BandWorkspace<S> ws() {
    return {{words.data(), words.size()}, {points.data(), points.size()},
            {vertices.data(), vertices.size()}};
  }
  std::vector<std::uint32_t> words;
  std::vector<kerf::Vec2<S>> points;
  std::vector<kerf::fit::BandVertex<S>> vertices;
  std::vector<kerf::fit::Piece<S>> pieces;
};

template <class S>
struct BandRun {
  kerf::Result<kerf::fit::Fit<S>> fit = kerf::Status::invalid_argument;
  std::vector<kerf_test::VPiece> pieces;  // in double, for the referee
};

template <class S>
BandRun<S> fit_band(const std::vector<VD>& pd, double tol) {
  std::vector<kerf::Vec2<S>> p;
  for (const VD& v : pd) p.push_back(from_d<S>(v));
  const std::vector<kerf::fit::BandWidth<S>> w(pd.size(), {from_d<S>(tol), from_d<S>(tol)});
  BandBuffers<S> buf(pd.size());
  BandRun<S> run;
  run.fit = kerf::fit::fit_band_min_count<S>({p.data(), p.size()}, {w.data(), w.size()}, buf.ws(),
                                             {buf.pieces.data(), buf.pieces.size()});
  if (!run.fit.ok()) return run;
  for (std::uint32_t k = 0; k < run.fit.value().pieces; ++k) {
    const kerf::fit::Piece<S>& f = buf.pieces[k];
    const kerf::Segment<double> s = to_d(f.segment);
    kerf_test::VPiece v;
    v.arc = s.is_arc();
    v.first = f.first;
    v.last = f.last;
    v.sx = s.start.x;
    v.sy = s.start.y;
    v.ex = s.end.x;
    v.ey = s.end.y;
    v.cx = s.centre.x;
    v.cy = s.centre.y;
    v.dir = s.dir;
    run.pieces.push_back(v);
  }
  return run;
}

// Checks one path: the count against double's (given), the chain of pieces,
// and each piece inside the band in double. Returns the piece count.
template <class S>
std::uint32_t check_path(const std::vector<VD>& pd, double tol, const std::string& what) {
  const BandRun<S> run = fit_band<S>(pd, tol);
  EXPECT_TRUE(run.fit.ok()) << what;
  if (!run.fit.ok()) return 0;
  std::vector<kerf_test::VPoint> vp;
  for (const VD& p : pd) vp.push_back({p.x, p.y});
  const kerf_test::BandWidths widths = kerf_test::symmetric_widths(pd.size(), tol);
  const double slack = allowance<S>(pd);
  std::size_t expect_first = 0;
  for (const kerf_test::VPiece& piece : run.pieces) {
    EXPECT_EQ(piece.first, expect_first) << what;
    expect_first = piece.last;
    double worst = 0;
    EXPECT_TRUE(kerf_test::arc_in_band(vp, widths, piece, slack, &worst))
        << what << ": piece " << piece.first << ".." << piece.last << " leaves the band by "
        << worst << " (allowed " << slack << ")";
  }
  EXPECT_EQ(expect_first, pd.size() - 1) << what;
  return run.fit.value().pieces;
}

struct BandCase {
  const char* curve;
  double tol;
};
constexpr BandCase band_cases[] = {
    {"parabola.txt", 0.0183}, {"parabola.txt", 0.0085}, {"parabola.txt", 0.05},
    {"parabola.txt", 0.2},    {"circle.txt", 0.01},     {"circle.txt", 0.05},
    {"ellipse.txt", 0.01},    {"ellipse.txt", 0.05},    {"ellipse.txt", 0.2},
    {"sine.txt", 0.01},       {"sine.txt", 0.05},       {"spiral.txt", 0.05},
    {"spiral.txt", 0.1},
};

TYPED_TEST(TypedBand, CountsMatchDoubleOnTheTestCurvesAndPiecesStayInTheBand) {
  using S = TypeParam;
  for (const BandCase& c : band_cases) {
    const std::vector<VD> pd = kerf::test::load_curve(c.curve);
    ASSERT_GT(pd.size(), 2u) << c.curve;
    const std::string what = std::string(c.curve) + " tol " + std::to_string(c.tol);
    const BandRun<double> want = fit_band<double>(pd, c.tol);
    ASSERT_TRUE(want.fit.ok()) << what;
    EXPECT_EQ(check_path<S>(pd, c.tol, what), want.fit.value().pieces) << what;
  }
}

// An airfoil (issue 25): small nose radii far from the origin, 300 mm chord.
TYPED_TEST(TypedBand, AirfoilCountsMatchDoubleAndPiecesStayInTheBand) {
  using S = TypeParam;
  for (const char* code : {"2412", "0012"}) {
    const std::vector<VD> pd = kerf::test::naca4(code);
    for (const double tol : {0.05, 0.02, 0.01, 0.005}) {
      const std::string what = std::string("NACA ") + code + " tol " + std::to_string(tol);
      const BandRun<double> want = fit_band<double>(pd, tol);
      ASSERT_TRUE(want.fit.ok()) << what;
      EXPECT_EQ(check_path<S>(pd, tol, what), want.fit.value().pieces) << what;
    }
  }
}

// The G1 polylines of the three cncjs CNC files (real G-code,
// tests/data/gcode), as `kerf weld` extracts them, each fitted on its own;
// consecutive repeated points are dropped, as the point reader does.
TYPED_TEST(TypedBand, CountsMatchDoubleOnTheGcodeCorpus) {
  using S = TypeParam;
  const char* files[] = {"cncjs_Circle_Diamond_Square_Calibration.gcode", "cncjs_jsdc-laser.gcode",
                         "cncjs_tball-engrave.gcode"};
  const double tol = 0.025;  // kerf weld's default
  for (const char* name : files) {
    const kerf::job::GcodeFile g = kerf::job::read_gcode(std::string(KERF_TEST_DATA_DIR) + "/gcode/" + name);
    ASSERT_TRUE(g.ok) << name << ":" << g.line << ": " << g.reason;
    std::uint32_t total_d = 0, total_s = 0;
    std::size_t paths = 0;
    for (std::size_t p = 0; p < g.polylines.size(); ++p) {
      std::vector<VD> pd;
      for (const VD& v : g.polylines[p].points)
        if (pd.empty() || !(pd.back() == v)) pd.push_back(v);
      if (pd.size() < 3) continue;
      const std::string what = std::string(name) + " polyline " + std::to_string(p + 1);
      const BandRun<double> want = fit_band<double>(pd, tol);
      ASSERT_TRUE(want.fit.ok()) << what;
      const std::uint32_t got = check_path<S>(pd, tol, what);
      EXPECT_EQ(got, want.fit.value().pieces) << what;
      total_d += want.fit.value().pieces;
      total_s += got;
      ++paths;
    }
    EXPECT_EQ(total_s, total_d) << name;
    EXPECT_GT(paths, 0u) << name;
    std::printf("%s: %zu polylines, %u pieces in double, %u in this type\n", name, paths, total_d, total_s);
  }
}

}  // namespace
