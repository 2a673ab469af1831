// `kerf sim` streams its job (issue 24): a generated G-code program of 1e4,
// 1e5 and 1e6 lines runs whole, each segment once, and the peak RSS at 1e6
// lines is at most 1.2 times that at 1e4 plus 16 MB (before, the program and
// its fitted job were held whole: about 370 bytes a line, 375 MB at 1e6).
// Short moves at a high feed keep the simulated time small; each size runs
// in a child process for its own peak RSS. Label scale (tests/link/CMakeLists.txt).
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "simulated/sim_command.hpp"

namespace kerf::test {
namespace {

constexpr long kPerPath = 500;  // G1 lines a path: 25 mm of a wave, 0.05 mm a line

// n G1 lines in paths of kPerPath, each pierced (M3) and ended (M5), rows of
// paths across the table, at F6000.
std::string write_program(const std::string& path, long n) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) return {};
  std::fprintf(f, "G21 G90\nF6000\n");
  for (long k = 0, row = 0; k < n; k += kPerPath, ++row) {
    const double y0 = 10.0 + 3.0 * static_cast<double>(row % 100), x0 = 10.0 + 40.0 * static_cast<double>(row / 100);
    std::fprintf(f, "G0 X%.3f Y%.3f\nM3 S1\n", x0, y0);
    for (long j = 0; j < kPerPath && k + j < n; ++j) {
      const double t = 0.05 * static_cast<double>(j);
      std::fprintf(f, "G1 X%.3f Y%.3f\n", x0 + t, y0 + std::sin(t / 2.0));
    }
    std::fprintf(f, "M5\n");
  }
  std::fprintf(f, "M2\n");
  return std::fclose(f) == 0 ? path : std::string();
}

double json_number(const std::string& text, const std::string& key) {
  const std::size_t at = text.find("\"" + key + "\": ");
  return at == std::string::npos ? -1.0 : std::stod(text.substr(at + key.size() + 4));
}

struct Peak {
  int rc = -1;
  long rss_kb = 0;
  double wall_s = 0, sim_s = 0, paths = 0, planned = 0, executed = 0, duplicates = 0;
};

// run_sim in a child process, so that each size has its own peak RSS.
Peak run_in_child(const simulated::SimOptions& o) {
  Peak p;
  const auto t0 = std::chrono::steady_clock::now();
  std::fflush(stdout);
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    ::_exit(simulated::run_sim(o));
  }
  int status = 0;
  rusage use{};
  if (pid < 0 || ::wait4(pid, &status, 0, &use) != pid) return p;
  p.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  p.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  p.rss_kb = use.ru_maxrss;
  std::ifstream f(o.report);
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string rep = ss.str();
  p.sim_s = json_number(rep, "duration_s");
  p.paths = json_number(rep, "paths");
  p.planned = json_number(rep, "segments_planned");
  p.executed = json_number(rep, "segments_executed");
  p.duplicates = json_number(rep, "duplicates");
  return p;
}

TEST(SimScale, AGcodeJobStreamsInFlatMemoryFrom1e4To1e6Lines) {
  const std::string dir = ::testing::TempDir() + "kerf_sim_scale_" + std::to_string(::getpid()) + "_";
  long smallest_kb = 0;
  for (const long n : {10000L, 100000L, 1000000L}) {
    simulated::SimOptions o;
    o.file = write_program(dir + std::to_string(n) + ".ngc", n);
    ASSERT_FALSE(o.file.empty());
    o.criterion = "vertex";  // the band fit takes 3 times as long
    o.report = dir + "report.json";
    const Peak p = run_in_child(o);
    std::remove(o.file.c_str());
    std::remove(o.report.c_str());
    std::printf("%8ld lines: max RSS %.1f MB, %.2f s wall, %.0f s simulated, %.0f paths, %.0f segments\n", n,
                static_cast<double>(p.rss_kb) / 1024.0, p.wall_s, p.sim_s, p.paths, p.planned);
    ASSERT_EQ(p.rc, 0) << n << " lines";
    EXPECT_EQ(p.paths, static_cast<double>((n + kPerPath - 1) / kPerPath)) << n << " lines";
    EXPECT_GT(p.planned, 0.0);
    EXPECT_EQ(p.executed, p.planned) << n << " lines: every segment";
    EXPECT_EQ(p.duplicates, 0.0) << n << " lines: each once";
    if (smallest_kb == 0) smallest_kb = p.rss_kb;
    EXPECT_LE(static_cast<double>(p.rss_kb), 1.2 * static_cast<double>(smallest_kb) + 16 * 1024.0) << n << " lines";
  }
}

}  // namespace
}  // namespace kerf::test
