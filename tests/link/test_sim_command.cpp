// `kerf sim` end to end: fit, the simulated board running core/motion's
// interpolator, the Modbus link, faults, report and trace. The trace is in
// drive counts (1 um), so it must sit on the fitted path to within the
// rounding of the counts (half a count per axis) and of the wire (the same
// again): 1.5 um, well inside the tol + 1 count.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "simulated/sim_command.hpp"
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
    // Names of their own: ctest runs the cases in parallel processes.
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info->name();  // "Case/tcp"
    for (char& c : name)
      if (c == '/') c = '_';
    dir_ = ::testing::TempDir() + "kerf_sim_" + std::to_string(::getpid()) + "_" + name + "_";
    points_ = dir_ + "points.txt";
    std::ofstream f(points_);
    // A zigzag: any three points lie on a circle, so about one arc per two
    // steps: a few hundred segments, many more than the board's queue.
    for (int i = 0; i <= 600; ++i) f << i * 0.5 << ' ' << ((i % 2) != 0 ? 0.3 : 0.0) << '\n';
  }
  simulated::SimOptions options() const {
    simulated::SimOptions o;
    o.link = GetParam() == Wire::tcp ? "modbus-tcp" : "modbus-rtu";
    o.tol = "0.01";
    o.report = dir_ + "report.json";
    o.trace = dir_ + "trace.csv";
    o.link_timeout = "0.5";
    o.file = points_;
    std::remove(o.report.c_str());
    std::remove(o.trace.c_str());
    return o;
  }
  static int run(const simulated::SimOptions& o) { return simulated::run_sim(o); }
  void TearDown() override {
    for (const char* f : {"points.txt", "report.json", "trace.csv"}) std::remove((dir_ + f).c_str());
  }
  std::string dir_, points_;
};

TEST_P(SimCommand, CleanJobIsExecutedOnceOnThePath) {
  const simulated::SimOptions o = options();
  ASSERT_EQ(run(o), 0);
  const std::string rep = slurp(o.report);
  EXPECT_NE(rep.find("\"state\": \"done\""), std::string::npos) << rep;
  EXPECT_NE(rep.find("\"fault\": null"), std::string::npos);
  EXPECT_NE(rep.find("\"torch_on\": false"), std::string::npos);
  const double planned = json_number(rep, "segments_planned");
  EXPECT_GT(planned, 100.0);
  EXPECT_EQ(json_number(rep, "segments_executed"), planned);
  EXPECT_EQ(json_number(rep, "segments_executed_total"), planned);
  EXPECT_EQ(json_number(rep, "duplicates"), 0.0);
  EXPECT_EQ(json_number(rep, "pierces"), 1.0);
  const double deviation = json_number(rep, "max_path_deviation_mm");
  EXPECT_GE(deviation, 0.0);
  EXPECT_LE(deviation, 0.0015);
  EXPECT_LE(deviation, 0.01 + 0.001);  // tol + 1 count
  // At 50 mm/s the path's ~350 mm take ~7 s of simulated time.
  EXPECT_GT(json_number(rep, "duration_s"), 6.0);
  const std::string trace = slurp(o.trace);
  ASSERT_EQ(trace.rfind("t_s,x_mm,y_mm,segment,torch,thc_lock\n", 0), 0u);
  std::istringstream lines(trace.substr(trace.find('\n') + 1));
  std::string line;
  unsigned previous = 0, samples = 0;
  while (std::getline(lines, line)) {  // segment numbers never go back
    unsigned seg = 0;
    double t = 0, x = 0, y = 0;
    int torch = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%u,%d", &t, &x, &y, &seg, &torch), 5) << line;
    if (seg == 0) continue;
    EXPECT_GE(seg, previous);
    EXPECT_EQ(torch, 1);
    previous = seg;
    ++samples;
  }
  EXPECT_EQ(previous, static_cast<unsigned>(planned));
  EXPECT_GT(samples, 6000u);
}

TEST_P(SimCommand, ShortLinkDropIsRidden) {
  simulated::SimOptions o = options();
  o.faults = {"link-drop@1.0:0.2", "modbus-exception@1.1"};  // while cutting (the pierce takes 0.55 s)
  o.link_timeout = "2";
  ASSERT_EQ(run(o), 0);
  const std::string rep = slurp(o.report);
  EXPECT_NE(rep.find("\"state\": \"done\""), std::string::npos) << rep;
  EXPECT_EQ(json_number(rep, "segments_executed"), json_number(rep, "segments_planned"));
  EXPECT_GE(json_number(rep, "link_errors"), 1.0);
}

TEST_P(SimCommand, LinkDownTooLongStopsAndReportsTheLastSegment) {
  simulated::SimOptions o = options();
  o.faults = {"link-stall@1.0:3"};
  ASSERT_EQ(run(o), 1);
  const std::string rep = slurp(o.report);
  EXPECT_NE(rep.find("\"state\": \"fault\""), std::string::npos) << rep;
  EXPECT_NE(rep.find("link down for more than 0.5 s"), std::string::npos) << rep;
  EXPECT_NE(rep.find("\"torch_on\": false"), std::string::npos);
  const double last = json_number(rep, "last_executed_segment");
  EXPECT_GE(last, 1.0);
  EXPECT_LT(last, json_number(rep, "segments_planned"));
  // The board runs on, blind, until its watchdog stops it: it may have
  // completed more than the controller saw (and journaled).
  EXPECT_GE(json_number(rep, "segments_executed"), last);
}

TEST_P(SimCommand, CrcErrorsAreRiddenOverRtuAndRefusedOverTcp) {
  simulated::SimOptions o = options();
  o.faults = {"crc-error@1.0", "crc-error@1.5"};
  if (GetParam() == Wire::tcp) {
    ASSERT_EQ(run(o), 2);  // TCP frames carry no CRC
    std::FILE* f = std::fopen(o.report.c_str(), "r");  // nothing written
    EXPECT_EQ(f, nullptr);
    if (f != nullptr) std::fclose(f);
    return;
  }
  ASSERT_EQ(run(o), 0);
  const std::string rep = slurp(o.report);
  EXPECT_NE(rep.find("\"state\": \"done\""), std::string::npos) << rep;
  EXPECT_EQ(json_number(rep, "segments_executed"), json_number(rep, "segments_planned"));
  EXPECT_GE(json_number(rep, "link_errors"), 2.0);
}

INSTANTIATE_TEST_SUITE_P(Wires, SimCommand, ::testing::Values(Wire::tcp, Wire::rtu), wire_name);

}  // namespace
}  // namespace kerf::test

namespace kerf::test {
namespace {

// A G-code job (by its extension): its torch-on moves, split into paths at
// rapids, fitted and cut like a point file's paths.
TEST(SimCommandGcode, RunsAGcodeJobPathByPath) {
  simulated::SimOptions o;
  o.file = std::string(KERF_GCODE_DIR) + "/cncjs_jsdc-laser.gcode";
  o.report = ::testing::TempDir() + "kerf_sim_gcode_" + std::to_string(::getpid()) + ".json";
  ASSERT_EQ(simulated::run_sim(o), 0);
  const std::string rep = slurp(o.report);
  EXPECT_NE(rep.find("\"state\": \"done\""), std::string::npos) << rep;
  EXPECT_EQ(json_number(rep, "paths"), 5.0);  // J, S, D's outside and inside, C
  EXPECT_EQ(json_number(rep, "pierces"), 5.0);
  EXPECT_EQ(json_number(rep, "segments_executed"), json_number(rep, "segments_planned"));
  EXPECT_LE(json_number(rep, "max_path_deviation_mm"), 0.025 + 0.001);
  std::remove(o.report.c_str());
}

}  // namespace
}  // namespace kerf::test
