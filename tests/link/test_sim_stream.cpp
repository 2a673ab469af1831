// `kerf sim` on the streamed job is the run of the job held whole: the same
// trace, byte for byte, and the same report (its wall time aside), on G-code
// programs (a dry run, one with actions, several materials) and a point
// file of several paths, over Modbus and CAN. The whole job
// (SimOptions::whole_job) is read and fitted before the run, as kerf sim
// did before issue 24: the oracle. Equal traces mean equal simulated time,
// so the producer's speed does not leak into the simulation.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
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

Run sim(const std::string& file, const std::string& link, bool whole, const std::string& criterion) {
  const std::string dir = ::testing::TempDir() + "kerf_sim_stream_" + std::to_string(::getpid()) + "_";
  simulated::SimOptions o;
  o.file = file;
  o.link = link;
  o.whole_job = whole;
  o.criterion = criterion;
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

void expect_same_run(const std::string& file, const std::string& link, const std::string& criterion = {}) {
  const Run whole = sim(file, link, true, criterion), streamed = sim(file, link, false, criterion);
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

namespace kerf::test {
namespace {

// 1e5 lines in paths of 500 (as test_sim_scale.cpp's): the producer's ring
// holds about 90 paths, so it falls behind the run after the first ring.
std::string write_long_program(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) return {};
  std::fprintf(f, "G21 G90\nF6000\n");
  for (long row = 0; row < 200; ++row) {
    const double y0 = 10.0 + 3.0 * static_cast<double>(row % 100), x0 = 10.0 + 40.0 * static_cast<double>(row / 100);
    std::fprintf(f, "G0 X%.3f Y%.3f\nM3 S1\n", x0, y0);
    for (long j = 0; j < 500; ++j) {
      const double t = 0.05 * static_cast<double>(j);
      std::fprintf(f, "G1 X%.3f Y%.3f\n", x0 + t, y0 + std::sin(t / 2.0));
    }
    std::fprintf(f, "M5\n");
  }
  std::fprintf(f, "M2\n");
  return std::fclose(f) == 0 ? path : std::string();
}

// Simulated time stands still while the producer is behind: the run is the
// whole job's however slowly the file is fitted (label scale: a few seconds).
TEST(SimStreamScale, AProducerBehindTheRunLeavesTheRunAsTheWholeJobs) {
  const std::string file =
      write_long_program(::testing::TempDir() + "kerf_sim_stream_long_" + std::to_string(::getpid()) + ".ngc");
  ASSERT_FALSE(file.empty());
  expect_same_run(file, "modbus-tcp", "vertex");  // the band fit takes 3 times as long
  expect_same_run(file, "can", "vertex");
  std::remove(file.c_str());
}

}  // namespace
}  // namespace kerf::test
