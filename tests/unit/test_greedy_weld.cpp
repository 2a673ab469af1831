// kerf's fewest-pieces search against the greedy welder (ArcWelder's rule,
// tests/support/greedy_weld.hpp) with the same exact pair test, on two real
// files: never more pieces on any polyline, and fewer on each file (measured
// by kerf_bench_greedy: 71 against 74 and 67 against 71 with the vertex test,
// 75 against 78 and 69 against 74 with the band at tol 0.025).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "greedy_weld.hpp"
#include "job/gcode_reader.hpp"

namespace {

void expect_optimal_below_greedy(kerf_test::WeldRule rule, const char* rule_name) {
  for (const char* name : {"cncjs_jsdc-laser.gcode", "cncjs_tball-engrave.gcode"}) {
    const kerf::job::GcodeFile g = kerf::job::read_gcode(std::string(KERF_TEST_DATA_DIR) + "/gcode/" + name);
    ASSERT_TRUE(g.ok) << name << ":" << g.line << ": " << g.reason;
    std::size_t optimal = 0, greedy = 0;
    for (std::size_t k = 0; k < g.polylines.size(); ++k) {
      const std::vector<kerf::Vec2<double>> p = kerf_test::distinct_points(g.polylines[k].points);
      if (p.size() < 2) continue;
      const std::uint32_t o = kerf_test::optimal_pieces(p, 0.025, rule);
      const std::uint32_t gr = kerf_test::greedy_pieces(p, 0.025, rule);
      ASSERT_GT(o, 0u) << name << " polyline " << k + 1;
      EXPECT_LE(o, gr) << name << " polyline " << k + 1 << " " << rule_name;
      optimal += o;
      greedy += gr;
    }
    EXPECT_LT(optimal, greedy) << name << " " << rule_name;
  }
}

TEST(GreedyWeld, OptimalNeverAboveGreedyAndBelowItOnRealFilesVertex) {
  expect_optimal_below_greedy(kerf_test::WeldRule::vertex, "vertex");
}

TEST(GreedyWeld, OptimalNeverAboveGreedyAndBelowItOnRealFilesBand) {
  expect_optimal_below_greedy(kerf_test::WeldRule::band, "band");
}

}  // namespace
