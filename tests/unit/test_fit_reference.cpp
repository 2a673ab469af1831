// The report's parabola, y = 300 - 200 (1 - x/500)^2 at x = linspace(500, 0, 200),
// against the exact reference figures (tests/data/curves/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "io/fit_storage.hpp"
#include "kerf/fit/fit.hpp"

namespace {

using kerf::Status;
using kerf::fit::Method;
using V = kerf::Vec2<double>;

std::vector<V> load(const std::string& name) {
  std::ifstream in(std::string(KERF_TEST_DATA_DIR) + "/curves/" + name);
  std::vector<V> p;
  double x, y;
  while (in >> x >> y) p.push_back({x, y});
  return p;
}

struct Fitter {
  explicit Fitter(std::size_t n) : storage(n) {}
  kerf::fit::Workspace<double> ws() { return storage.workspace(); }
  kerf::Result<kerf::fit::Fit<double>> count(const std::vector<V>& p, double tol, Method m) {
    return kerf::fit::fit_min_count<double>({p.data(), p.size()}, tol, m, ws(), storage.pieces());
  }
  kerf::Result<kerf::fit::Fit<double>> budget(const std::vector<V>& p, unsigned k, Method m) {
    return kerf::fit::fit_min_error<double>({p.data(), p.size()}, k, m, ws(), storage.pieces());
  }
  const kerf::fit::Piece<double>& out(std::size_t k) const { return storage.piece(k); }
  kerf::io::FitStorage storage;
};

class Parabola : public ::testing::Test {
 protected:
  void SetUp() override {
    pts = load("parabola.txt");
    ASSERT_EQ(pts.size(), 200u);
  }
  std::vector<V> pts;
};

TEST_F(Parabola, OptimalCountsMatchTheReference) {
  Fitter f(pts.size());
  const std::pair<double, unsigned> cases[] = {{0.0183, 5}, {0.0085, 7}, {0.05, 4}, {0.1, 3}};
  for (const auto& [tol, pieces] : cases) {
    const auto r = f.count(pts, tol, Method::optimal);
    ASSERT_TRUE(r.ok()) << kerf::to_string(r.status());
    EXPECT_EQ(r.value().pieces, pieces) << "tol " << tol;
    EXPECT_LE(r.value().max_error, tol);
    EXPECT_EQ(r.value().tol, tol);
  }
}

TEST_F(Parabola, TieBreakReachesTheSmallestErrorForTheCount) {
  Fitter f(pts.size());
  // Among all 5-piece solutions at tol 0.0183, the best has max error 0.0161900.
  const auto r = f.count(pts, 0.0183, Method::optimal);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.value().max_error, 0.0161900, 1e-6);
}

TEST_F(Parabola, MinEpsBeatsTheReportsFigures) {
  Fitter f(pts.size());
  const auto five = f.budget(pts, 5, Method::optimal);
  ASSERT_TRUE(five.ok());
  EXPECT_EQ(five.value().pieces, 5u);
  EXPECT_NEAR(five.value().tol, 0.0161900, 1e-6);
  EXPECT_LT(five.value().tol, 0.0183);
  const auto seven = f.budget(pts, 7, Method::optimal);
  ASSERT_TRUE(seven.ok());
  EXPECT_EQ(seven.value().pieces, 7u);
  EXPECT_NEAR(seven.value().tol, 0.00584591, 1e-6);
  EXPECT_LT(seven.value().tol, 0.0085);
  // Minimal: just below the found tol, the budget no longer suffices.
  const auto below = f.count(pts, five.value().tol * (1 - 1e-6), Method::optimal);
  ASSERT_TRUE(below.ok());
  EXPECT_GT(below.value().pieces, 5u);
}

TEST_F(Parabola, EsgiRulesReproduceTheReportsCounts) {
  // The report: 5 arcs at max error about 0.0183, 7 at less than 0.0085. Both
  // rules restricted to their own arcs need no more pieces than that here.
  Fitter f(pts.size());
  for (const Method m : {Method::esgi_max, Method::esgi_mean}) {
    const auto five = f.count(pts, 0.0183, m);
    ASSERT_TRUE(five.ok());
    EXPECT_EQ(five.value().pieces, 5u);
    const auto seven = f.count(pts, 0.0085, m);
    ASSERT_TRUE(seven.ok());
    EXPECT_EQ(seven.value().pieces, 7u);
    // A rule is a restriction of the exact criterion: never better than optimal.
    const auto best = f.budget(pts, 5, m);
    ASSERT_TRUE(best.ok());
    EXPECT_GE(best.value().tol, 0.0161900 - 1e-7);
  }
}

TEST_F(Parabola, PiecesAreCounterClockwiseArcsThroughInputPoints) {
  Fitter f(pts.size());
  const auto r = f.count(pts, 0.0183, Method::optimal);
  ASSERT_TRUE(r.ok());
  std::uint32_t at = 0;
  for (unsigned k = 0; k < r.value().pieces; ++k) {
    const auto& piece = f.out(k);
    EXPECT_EQ(piece.first, at);
    EXPECT_TRUE(piece.segment.is_arc());
    // x runs from 500 down to 0 along a parabola opening downwards: it turns left.
    EXPECT_EQ(piece.segment.dir, 1);
    EXPECT_EQ(piece.segment.start, pts[piece.first]);
    EXPECT_EQ(piece.segment.end, pts[piece.last]);
    at = piece.last;
  }
  EXPECT_EQ(at, 199u);
}

TEST(FitArguments, BadInputIsAStatusNotACrash) {
  const std::vector<V> pts{{0, 0}, {1, 0}, {2, 1}};
  Fitter f(pts.size());
  EXPECT_EQ(f.count(pts, 0.0, Method::optimal).status(), Status::invalid_argument);
  EXPECT_EQ(f.count(pts, -1.0, Method::optimal).status(), Status::invalid_argument);
  EXPECT_EQ(f.count(pts, std::nan(""), Method::optimal).status(), Status::invalid_argument);
  EXPECT_EQ(f.count(pts, INFINITY, Method::optimal).status(), Status::invalid_argument);
  EXPECT_EQ(f.budget(pts, 0, Method::optimal).status(), Status::invalid_argument);
  const std::vector<V> one{{1, 1}};
  EXPECT_EQ(f.count(one, 0.1, Method::optimal).status(), Status::invalid_argument);
  const std::vector<V> nan{{0, 0}, {std::nan(""), 1}, {2, 2}};
  EXPECT_EQ(f.count(nan, 0.1, Method::optimal).status(), Status::invalid_argument);
  const std::vector<V> dup{{0, 0}, {1, 1}, {1, 1}, {2, 0}};
  EXPECT_EQ(f.count(dup, 0.1, Method::optimal).status(), Status::degenerate);
}

TEST(FitArguments, SmallStorageIsReportedNotTruncated) {
  std::vector<V> pts;
  for (int k = 0; k < 50; ++k) pts.push_back({k * 1.0, (k % 2) * 1.0});  // zig-zag: 49 pieces
  Fitter f(pts.size());
  std::vector<kerf::fit::Piece<double>> few(3);
  const auto r = kerf::fit::fit_min_count<double>({pts.data(), pts.size()}, 0.1, Method::optimal,
                                                  f.ws(), {few.data(), few.size()});
  EXPECT_EQ(r.status(), Status::capacity_exceeded);
  std::vector<std::uint32_t> words(10);
  kerf::fit::Workspace<double> small = f.ws();
  small.words = {words.data(), words.size()};
  EXPECT_EQ(kerf::fit::count_min<double>({pts.data(), pts.size()}, 0.1, Method::optimal, small).status(),
            Status::capacity_exceeded);
}

}  // namespace
