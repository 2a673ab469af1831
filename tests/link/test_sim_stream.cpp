// `kerf sim` on the streamed job is the run of the job held whole: the same
// trace, byte for byte, and the same report (its wall time aside), on G-code
// programs (a dry run, one with actions, several materials) and a point
// file of several paths, over Modbus and CAN. The whole job
// (SimOptions::whole_job) is read and fitted before the run, as kerf sim
// did before issue 24: the oracle. Equal traces mean equal simulated time,
// so the producer's speed does not leak into the simulation.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "simulated/sim_command.hpp"

namespace kerf::test {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// The report without its wall-time line.
std::string without_wall(const std::string& report) {
  std::istringstream in(report);
  std::string line, out;
  while (std::getline(in, line))
    if (line.find("\"wall_s\"") == std::string::npos) out += line + '\n';
  return out;
}

struct Run {
  int rc = -1;
  std::string trace, report;
};

Run sim(const std::string& file, const std::string& link, bool whole) {
  const std::string dir = ::testing::TempDir() + "kerf_sim_stream_" + std::to_string(::getpid()) + "_";
  simulated::SimOptions o;
  o.file = file;
  o.link = link;
  o.whole_job = whole;
  o.trace = dir + "trace.csv";
  o.report = dir + "report.json";
  Run r;
  r.rc = simulated::run_sim(o);
  r.trace = slurp(o.trace);
  r.report = without_wall(slurp(o.report));
  std::remove(o.trace.c_str());
  std::remove(o.report.c_str());
  return r;
}

void expect_same_run(const std::string& file, const std::string& link) {
  const Run whole = sim(file, link, true), streamed = sim(file, link, false);
  ASSERT_EQ(whole.rc, 0) << file;
  EXPECT_EQ(streamed.rc, whole.rc) << file;
  EXPECT_GT(whole.trace.size(), 1000U) << file;
  EXPECT_TRUE(streamed.trace == whole.trace) << file << ": the traces differ (" << streamed.trace.size() << " and "
                                             << whole.trace.size() << " bytes)";
  EXPECT_EQ(streamed.report, whole.report) << file;
}

const std::string kGcode = KERF_GCODE_DIR;

TEST(SimStream, ADryRunProgramRunsAsTheWholeJob) { expect_same_run(kGcode + "/cncjs_tball-engrave.gcode", "modbus-tcp"); }

TEST(SimStream, AProgramWithActionsRunsAsTheWholeJob) {
  expect_same_run(kGcode + "/linuxcnc_plasmac_metric_wrench.ngc", "modbus-tcp");
}

TEST(SimStream, AProgramWithMaterialsRunsAsTheWholeJobOnCan) {
  expect_same_run(kGcode + "/linuxcnc_plasmac_metric_material_change.ngc", "can");
}

TEST(SimStream, APointFileOfFourPathsRunsAsTheWholeJob) {
  expect_same_run(kGcode + "/../../../firmware/examples/demo_job.txt", "modbus-tcp");
  expect_same_run(kGcode + "/../../../firmware/examples/demo_job.txt", "can");
}

}  // namespace
}  // namespace kerf::test
