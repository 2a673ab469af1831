// `kerf sim`'s streaming path end to end (fit, board, link, faults, report,
// trace) with the board's EndpointExecutor standing in for the motion
// executor: every executed sample is a segment end, so the trace must sit on
// the fitted path to within one count (1 um) after the wire's rounding.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "cli/sim_command.hpp"
#include "link_rig.hpp"

namespace kerf::test {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// The number after "key": in the report.
double json_number(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return -1.0;
  return std::stod(json.substr(at + key.size() + 4));
}

class SimCommand : public ::testing::TestWithParam<Wire> {
 protected:
  void SetUp() override {
    dir_ = ::testing::TempDir();
    points_ = dir_ + "kerf_sim_points.txt";
    std::ofstream f(points_);
    // A zigzag: any three points lie on a circle, so about one arc per two
    // steps: a few hundred segments, many more than the board's queue.
    for (int i = 0; i <= 600; ++i) f << i * 0.5 << ' ' << ((i % 2) != 0 ? 0.3 : 0.0) << '\n';
  }
  cli::SimOptions options() const {
    cli::SimOptions o;
    o.link = GetParam() == Wire::tcp ? "modbus-tcp" : "modbus-rtu";
    o.tol = "0.01";
    o.report = dir_ + "kerf_sim_report.json";
    o.trace = dir_ + "kerf_sim_trace.csv";
    o.link_timeout = "0.5";
    o.file = points_;
    std::remove(o.report.c_str());
    std::remove(o.trace.c_str());
    return o;
  }
  static int run(const cli::SimOptions& o) {
    return cli::run_sim_with(o, [](std::string&) { return std::make_unique<sim::EndpointExecutor>(); });
  }
  std::string dir_, points_;
};

TEST_P(SimCommand, CleanJobIsExecutedOnceOnThePath) {
  const cli::SimOptions o = options();
  ASSERT_EQ(run(o), 0);
  const std::string rep = slurp(o.report);
  EXPECT_NE(rep.find("\"state\": \"done\""), std::string::npos) << rep;
  EXPECT_NE(rep.find("\"fault\": null"), std::string::npos);
  EXPECT_NE(rep.find("\"torch_on\": false"), std::string::npos);
  const double planned = json_number(rep, "segments_planned");
  EXPECT_GT(planned, 100.0);
  EXPECT_EQ(json_number(rep, "segments_sent"), planned);
  EXPECT_EQ(json_number(rep, "segments_executed"), planned);
  EXPECT_EQ(json_number(rep, "duplicates"), 0.0);
  EXPECT_LE(json_number(rep, "max_path_deviation_mm"), 0.001);
  const std::string trace = slurp(o.trace);
  EXPECT_EQ(trace.rfind("t_s,x_mm,y_mm,segment,torch\n", 0), 0u);
  // One sample at power-up, then one per segment (the endpoint executor).
  EXPECT_EQ(static_cast<double>(std::count(trace.begin(), trace.end(), '\n')), planned + 2.0);
}

TEST_P(SimCommand, ShortLinkDropIsRidden) {
  cli::SimOptions o = options();
  o.faults = {"link-drop@0.05:0.2", "modbus-exception@0.1"};
  ASSERT_EQ(run(o), 0);
  const std::string rep = slurp(o.report);
  EXPECT_NE(rep.find("\"state\": \"done\""), std::string::npos) << rep;
  EXPECT_EQ(json_number(rep, "segments_executed"), json_number(rep, "segments_planned"));
  EXPECT_GE(json_number(rep, "segments_resent"), 1.0);
}

TEST_P(SimCommand, LinkDownTooLongStopsAndReportsTheLastSegment) {
  cli::SimOptions o = options();
  o.faults = {"link-stall@0.05:3"};
  ASSERT_EQ(run(o), 1);
  const std::string rep = slurp(o.report);
  EXPECT_NE(rep.find("\"state\": \"fault\""), std::string::npos) << rep;
  EXPECT_NE(rep.find("link down for more than 0.5 s"), std::string::npos) << rep;
  EXPECT_NE(rep.find("\"torch_on\": false"), std::string::npos);
  const double last = json_number(rep, "last_executed_segment");
  EXPECT_GE(last, 1.0);
  EXPECT_LT(last, json_number(rep, "segments_planned"));
  EXPECT_EQ(json_number(rep, "segments_executed"), last);
}

INSTANTIATE_TEST_SUITE_P(Wires, SimCommand, ::testing::Values(Wire::tcp, Wire::rtu), wire_name);

}  // namespace
}  // namespace kerf::test
