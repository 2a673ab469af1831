// A path that goes round the same circle twice (pcb2gcode's helical holes
// once Z is taken out, a double pass) fools the fitters: one arc passes every
// point's band but cannot run the points in order. fit_job must still give a
// fit that passes its own check, never refuse the program.
#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
