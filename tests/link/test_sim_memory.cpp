// `kerf sim`'s memory does not grow with simulated time: the same job (the
// same lines, fitted to the same pieces) at a quarter of the feed runs four
// times as long in the same peak RSS. The trace streams to its consumers;
// before, every servo sample was kept (twice): about 120 B per simulated ms.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "simulated/sim_command.hpp"

namespace kerf::test {
namespace {

// Ten laps of a 100-gon of radius 50 mm at feed F (mm/min), torch on.
std::string write_laps(const std::string& path, int feed) {
  std::ofstream f(path);
  f << "G21 G90\nG0 X110 Y60\nM3 S1\nF" << feed << '\n';
  char line[64];
  for (int lap = 0; lap < 10; ++lap)
    for (int k = 1; k <= 100; ++k) {
      const double a = 2.0 * M_PI * k / 100.0;
      std::snprintf(line, sizeof line, "G1 X%.4f Y%.4f\n", 60 + 50 * std::cos(a), 60 + 50 * std::sin(a));
      f << line;
    }
  f << "M5\nM2\n";
  return path;
}

struct Peak {
  int rc = -1;
  long rss_kb = 0;
  double sim_s = 0;
};

// run_sim in a child process, so that each run has its own peak RSS.
Peak run_in_child(const simulated::SimOptions& o) {
  Peak p;
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(simulated::run_sim(o));
  int status = 0;
  rusage use{};
  if (pid < 0 || ::wait4(pid, &status, 0, &use) != pid) return p;
  p.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  p.rss_kb = use.ru_maxrss;
  std::ifstream f(o.report);
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string rep = ss.str();
  const std::size_t at = rep.find("\"duration_s\": ");
  if (at != std::string::npos) p.sim_s = std::stod(rep.substr(at + 14));
  return p;
}

TEST(SimMemory, PeakRssStaysFlatForAJobFourTimesLonger) {
  const std::string dir = ::testing::TempDir() + "kerf_sim_memory_" + std::to_string(::getpid()) + "_";
  Peak peak[2];
  const int feeds[2] = {1200, 300};
  for (int k = 0; k < 2; ++k) {
    simulated::SimOptions o;
    o.file = write_laps(dir + std::to_string(k) + ".ngc", feeds[k]);
    o.criterion = "vertex";  // fits in milliseconds
    o.report = dir + "report.json";
    o.plot = dir + "plot.svg";  // thinned to its budget
    peak[k] = run_in_child(o);
    for (const std::string& f : {o.file, o.report, o.plot}) std::remove(f.c_str());
    ASSERT_EQ(peak[k].rc, 0);
  }
  EXPECT_GT(peak[1].sim_s, 3.5 * peak[0].sim_s);
  EXPECT_GT(peak[0].sim_s, 100.0);
  // The whole trace kept was about 45 MB more for the longer run.
  EXPECT_LE(peak[1].rss_kb, peak[0].rss_kb + 4096)
      << peak[0].sim_s << " s: " << peak[0].rss_kb << " KiB; " << peak[1].sim_s << " s: " << peak[1].rss_kb << " KiB";
  std::printf("peak RSS %ld KiB for %.1f s simulated, %ld KiB for %.1f s\n", peak[0].rss_kb, peak[0].sim_s,
              peak[1].rss_kb, peak[1].sim_s);
}

}  // namespace
}  // namespace kerf::test
