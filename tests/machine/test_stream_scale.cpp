// A streamed point job's memory does not grow with its length: the
// StreamedJob (control/streamed_job.hpp: the id's pass over the bytes, the
// producer thread, its ring, the controller pulling from its source) at 1e4,
// 1e5 and 1e6 points in paths of 2000, each run in a child process for its
// own peak RSS. Label scale (tests/machine/CMakeLists.txt).
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "control/streamed_job.hpp"
#include "simulated/sim_machine.hpp"
#include "simulated/sim_plant.hpp"
#include "fake_gpio.hpp"

namespace kerf::test {
namespace {

// A zigzag of n points (about one segment per two points) in paths of 2000, written line by line.
std::string write_zigzag(long n) {
  const std::string dir = std::filesystem::temp_directory_path() / ("kerf_stream_scale_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/zigzag_" + std::to_string(n) + ".txt";
  std::FILE* f = std::fopen(path.c_str(), "w");
  for (long k = 0; k < n; ++k) {
    if (k > 0 && k % 2000 == 0) std::fprintf(f, "\n");
    std::fprintf(f, "%.3f %.3f\n", 0.2 * static_cast<double>(k % 2000), (k % 2) * 0.3 + 0.001 * static_cast<double>(k / 2000));
  }
  std::fclose(f);
  return path;
}

control::StreamedJobSetup setup() {
  control::StreamedJobSetup s;
  s.criterion = job::Criterion::vertex;
  s.tol = 0.01;
  s.feed_mm_s = 2000.0;
  return s;
}

// The child: 0 when the whole job was cut, each segment once.
int stream_run(const std::string& file) {
  control::StreamedJob streamed;
  std::string error;
  if (streamed.open(file, setup(), error) != 0 || streamed.prime(error) != 0) return 2;
  rusage u{};
  ::getrusage(RUSAGE_SELF, &u);
  std::printf("  primed: %.1f MB\n", static_cast<double>(u.ru_maxrss) / 1024.0);
  FakeGpio gpio;
  gpio.record_watchdog = false;  // an edge every cycle: the fixture's record would grow, not the controller
  control::ControllerConfig cfg;
  cfg.pierce_delay_s = 0.01;
  simulated::SimMachineConfig m;
  m.trace_sink = [](const sim::TraceSample&) {};
  m.max_sim_s = 1e6;
  std::unique_ptr<simulated::SimPlant> plant = simulated::make_modbus_plant(m, cfg.link_watchdog_s, error);
  if (!plant) return 4;
  const simulated::SimMachineResult r =
      simulated::run_sim_machine(streamed.source(), cfg, m, *plant, gpio, nullptr, {});
  const control::StreamTotals t = streamed.totals();
  std::printf("  %zu segments in %zu paths, %.0f s simulated\n", t.segments, t.paths, r.sim_s);
  const bool ok = r.setup_error.empty() && r.run.state == control::State::done && t.ended &&
                  r.run.completed_this_run == t.segments && streamed.source().segment_count() == t.segments;
  return ok ? 0 : 5;
}

struct Peak {
  int rc = -1;
  long rss_kb = 0;
  double wall_s = 0;
};

Peak in_child(const std::string& file) {
  Peak p;
  const auto t0 = std::chrono::steady_clock::now();
  std::fflush(stdout);
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int rc = stream_run(file);
    std::fflush(stdout);
    ::_exit(rc);
  }
  int status = 0;
  rusage use{};
  if (pid < 0 || ::wait4(pid, &status, 0, &use) != pid) return p;
  p.rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  p.rss_kb = use.ru_maxrss;
  p.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

TEST(StreamScale, APointJobStreamsInFlatMemoryFrom1e4To1e6Points) {
  long smallest_kb = 0;
  for (const long n : {10000L, 100000L, 1000000L}) {
    const std::string file = write_zigzag(n);
    const Peak p = in_child(file);
    std::filesystem::remove(file);
    std::printf("%8ld points: max RSS %.1f MB, %.2f s wall\n", n, static_cast<double>(p.rss_kb) / 1024.0, p.wall_s);
    ASSERT_EQ(p.rc, 0) << n << " points";
    if (smallest_kb == 0) smallest_kb = p.rss_kb;
    EXPECT_LE(static_cast<double>(p.rss_kb), 1.2 * static_cast<double>(smallest_kb) + 16 * 1024.0) << n << " points";
  }
}

}  // namespace
}  // namespace kerf::test
