// Every method's output on the project's curves (tests/data/curves), checked
// by the independent verifier (tests/support/verifier.hpp): fewest pieces at
// fixed tolerances, and the smallest tolerance for a piece budget, which must
// also be minimal.
#include <gtest/gtest.h>

#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "bridge/fit_bridge.hpp"
#include "verifier.hpp"

namespace {

using kerf_test::CoreFitter;
using kerf_test::Method;
using kerf_test::VPoint;

std::vector<VPoint> load(const std::string& name) {
  std::ifstream in(std::string(KERF_TEST_DATA_DIR) + "/curves/" + name);
  std::vector<VPoint> p;
  double x, y;
  while (in >> x >> y) p.push_back({x, y});
  return p;
}

struct Curve {
  const char* file;
  std::size_t points;
};

void PrintTo(const Curve& c, std::ostream* os) { *os << c.file; }

const Curve kCurves[] = {
    {"circle.txt", 100}, {"ellipse.txt", 200}, {"parabola.txt", 200},
    {"sine.txt", 400},   {"spiral.txt", 300},
};

class VerifiedOutputs : public ::testing::TestWithParam<Curve> {
 protected:
  void SetUp() override {
    pts = load(GetParam().file);
    ASSERT_EQ(pts.size(), GetParam().points) << "cannot read " << GetParam().file;
  }
  std::vector<VPoint> pts;
};

TEST_P(VerifiedOutputs, FewestPiecesAtFixedTolerances) {
  CoreFitter f(pts);
  for (const double tol : {0.001, 0.01, 0.1, 1.0}) {
    std::uint32_t optimal = 0;
    for (const Method m : kerf_test::kMethods) {
      SCOPED_TRACE(std::string(kerf_test::method_name(m)) + ", tol " + std::to_string(tol));
      const auto c = f.count(tol, m);
      ASSERT_TRUE(c.ok()) << kerf::to_string(c.status());
      const auto r = f.fit(tol, m);
      ASSERT_TRUE(r.ok()) << kerf::to_string(r.status());
      EXPECT_EQ(r.value().pieces, c.value());
      EXPECT_LE(r.value().max_error, tol);
      const kerf_test::VerifyReport v = kerf_test::verify(pts, f.pieces(r.value().pieces), tol,
                                                               m == Method::optimal ? kerf_test::Reach::arc : kerf_test::Reach::circle);
      EXPECT_TRUE(v.ok) << v.why;
      if (m == Method::optimal) optimal = r.value().pieces;
      else EXPECT_GE(r.value().pieces, optimal) << "a heuristic beat the optimum";
    }
  }
}

TEST_P(VerifiedOutputs, SmallestToleranceForABudgetIsVerifiedAndMinimal) {
  CoreFitter f(pts);
  const double floor = kerf_test::scale_of(pts) * 1e-12;  // the search's lower end
  for (const std::uint32_t budget : {2u, 4u, 7u}) {
    for (const Method m : kerf_test::kMethods) {
      // esgi_max tries every inner point's circle for every pair: on the
      // 300- and 400-point curves its bisection takes seconds. It runs on
      // the three smaller curves.
      if (m == Method::esgi_max && pts.size() > 200) continue;
      SCOPED_TRACE(std::string(kerf_test::method_name(m)) + ", budget " + std::to_string(budget));
      const auto r = f.budget(budget, m);
      ASSERT_TRUE(r.ok()) << kerf::to_string(r.status());
      const double tol = r.value().tol;
      EXPECT_GE(r.value().pieces, 1u);
      EXPECT_LE(r.value().pieces, budget);
      // The pieces' errors are measured after the search: equal to tol up to
      // rounding (1e-9 relative, the verifier's own allowance).
      EXPECT_LE(r.value().max_error, tol * (1 + 1e-9));
      const kerf_test::VerifyReport v = kerf_test::verify(pts, f.pieces(r.value().pieces), tol,
                                                               m == Method::optimal ? kerf_test::Reach::arc : kerf_test::Reach::circle);
      EXPECT_TRUE(v.ok) << v.why << " (at the returned tol " << tol << ")";
      // Minimal: just below the returned tol the budget no longer suffices
      // (unless the search stopped at its floor: the data are exact).
      if (tol > floor * (1 + 1e-6)) {
        const auto below = f.count(tol * (1 - 1e-6), m);
        ASSERT_TRUE(below.ok()) << kerf::to_string(below.status());
        EXPECT_GT(below.value(), budget) << "tol " << tol << " is not the smallest";
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Curves, VerifiedOutputs, ::testing::ValuesIn(kCurves),
                         [](const ::testing::TestParamInfo<Curve>& param) {
                           const std::string s = param.param.file;
                           return s.substr(0, s.find('.'));
                         });

}  // namespace
