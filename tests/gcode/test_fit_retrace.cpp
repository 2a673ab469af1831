// A path that goes round the same circle twice (pcb2gcode's helical holes
// once Z is taken out, a double pass) fools the fitters: one arc passes every
// point's band but cannot run the points in order. fit_job must still give a
// fit that passes its own check, never refuse the program.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "job/check_fit.hpp"
#include "job/fit_job.hpp"

namespace {

using kerf::Vec2;

std::vector<Vec2<double>> circle_twice(double r, int per_turn) {
  std::vector<Vec2<double>> pts;
  for (int i = 0; i <= 2 * per_turn; ++i) {
    const double a = 2.0 * 3.141592653589793 * i / per_turn;
    pts.push_back({10.0 + r * std::cos(a), 10.0 + r * std::sin(a)});
  }
  return pts;
}

void expect_fits(kerf::job::Criterion criterion, double r) {
  const std::vector<Vec2<double>> pts = circle_twice(r, 64);
  std::vector<kerf::fit::Piece<double>> pieces;
  std::string error;
  kerf::Status status{};
  ASSERT_TRUE(kerf::job::fit_job(pts, {}, 0.01, criterion, pieces, error, status)) << error;
  EXPECT_GE(pieces.size(), 2u);  // one arc cannot go round twice
  const kerf::Span<const Vec2<double>> p(pts.data(), pts.size());
  EXPECT_EQ(kerf::job::check_fit(p, {pieces.data(), pieces.size()}, 0.01), "");
}

TEST(FitRetrace, BandFitOfACircleRunTwicePassesItsOwnCheck) { expect_fits(kerf::job::Criterion::band, 5.0); }
TEST(FitRetrace, VertexFitOfACircleRunTwicePassesItsOwnCheck) { expect_fits(kerf::job::Criterion::vertex, 5.0); }
TEST(FitRetrace, SmallCircleRunTwice) { expect_fits(kerf::job::Criterion::band, 0.1); }

// The vertex fit measures the distance to the arc, not to its circle (issue
// 25): cncjs tball-pocket's zigzags put points near the other arc of a
// piece's circle, and the fit failed its own check at tol 0.01 to 0.1 (the
// split hid it). Now every path fits at once: no split is taken.
TEST(FitRetrace, TballPocketVertexFitsWithoutTheSplit) {
  kerf::io::PointFile f;
  ASSERT_TRUE(kerf::job::read_job(std::string(KERF_TEST_DATA_DIR) + "/gcode/cncjs_tball-pocket.gcode",
                                  kerf::job::Criterion::vertex, f));
  ASSERT_GE(f.path_begin.size(), 4u);
  const std::size_t before = kerf::job::fit_job_splits();
  std::size_t pieces_total = 0;
  for (const double tol : {0.01, 0.025, 0.05, 0.1}) {
    for (std::size_t k = 0; k < f.path_begin.size(); ++k) {
      const std::size_t end = k + 1 < f.path_begin.size() ? f.path_begin[k + 1] : f.points.size();
      const std::vector<Vec2<double>> pts(f.points.begin() + static_cast<std::ptrdiff_t>(f.path_begin[k]),
                                          f.points.begin() + static_cast<std::ptrdiff_t>(end));
      if (pts.size() < 2) continue;
      std::vector<kerf::fit::Piece<double>> pieces;
      std::string error;
      kerf::Status status{};
      ASSERT_TRUE(kerf::job::fit_job(pts, {}, tol, kerf::job::Criterion::vertex, pieces, error, status))
          << "path " << k << " tol " << tol << ": " << error;
      pieces_total += pieces.size();
    }
  }
  EXPECT_EQ(kerf::job::fit_job_splits(), before) << "a path was split: its fit failed its own check";
  EXPECT_GT(pieces_total, 0u);
}

}  // namespace
