// The window reading's peak memory on generated programs of 1e4, 1e5 and
// 1e6 lines (paths of 1000 short moves), each read in a child process
// (kerf_program_stream_probe) so that getrusage gives its own peak: at 1e6
// lines it is at most 1.2 x that at 1e4, plus 16 MB. The whole reading's
// figures are printed beside it (label scale: debug-asan leaves it out).
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

constexpr int kPathLines = 1000;

// `lines` lines: paths of kPathLines lines (a rapid, M3, the cut's moves of
// 0.1 mm, M5) in rows.
std::string generate(std::size_t lines) {
  const std::string path = ::testing::TempDir() + "kerf_window_" + std::to_string(lines) + ".nc";
  std::ofstream out(path, std::ios::binary);
  std::string buf;
  char line[64];
  for (std::size_t n = 0, k = 0; n < lines; ++k) {
    const double y = static_cast<double>(k % 100);
    buf += "G0 X0 Y" + std::to_string(static_cast<int>(y)) + "\nM3\n";
    for (int i = 1; i <= kPathLines - 3; ++i) {
      const int len = std::snprintf(line, sizeof line, i == 1 ? "G1 X%.3f Y%.3f F6000\n" : "G1 X%.3f Y%.3f\n",
                                    0.1 * i, y + 0.01 * (i % 7));
      buf.append(line, static_cast<std::size_t>(len));
    }
    buf += "M5\n";
    n += kPathLines;
    if (buf.size() > (1u << 20)) out << buf, buf.clear();
  }
  out << buf;
  return path;
}

struct ProbeRun {
  bool ok = false;
  long max_rss_kb = 0;
  double seconds = 0;
  std::string out;
};

ProbeRun probe(const std::string& file, const char* mode) {
  ProbeRun r;
  int fds[2];
  if (pipe(fds) != 0) return r;
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) return r;
  if (pid == 0) {
    dup2(fds[1], 1);
    close(fds[0]);
    close(fds[1]);
    execl(KERF_STREAM_PROBE, KERF_STREAM_PROBE, file.c_str(), mode, static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  char buf[512];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) r.out.append(buf, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  rusage ru{};
  if (wait4(pid, &status, 0, &ru) != pid) return r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.max_rss_kb = ru.ru_maxrss;
  r.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return r;
}

TEST(ProgramWindowScale, PeakMemoryDoesNotGrowWithTheFile) {
  long smallest = 0;
  for (const std::size_t n : {std::size_t{10000}, std::size_t{100000}, std::size_t{1000000}}) {
    const std::string file = generate(n);
    const ProbeRun w = probe(file, "window");
    ASSERT_TRUE(w.ok) << n << " lines: " << w.out;
    const std::size_t paths = n / kPathLines;
    // Each path: its rapid's end, then its moves.
    const std::string expect = "paths " + std::to_string(paths) + " points " +
                               std::to_string(paths * (kPathLines - 2)) + " actions 0 ";
    EXPECT_EQ(w.out.rfind(expect, 0), 0u) << w.out;
    // The whole reading, for the figures (it holds the file: up to ~400 MB at 1e6 lines).
    const ProbeRun h = probe(file, "whole");
    ASSERT_TRUE(h.ok) << h.out;
    EXPECT_EQ(h.out.substr(0, h.out.find(" first_path_s")), w.out.substr(0, w.out.find(" first_path_s")));
    auto first_path = [](const std::string& out) {  // "first_path_s S seconds S" from the probe's line
      const std::size_t at = out.find("first_path_s");
      return at == std::string::npos ? std::string() : out.substr(at, out.find('\n', at) - at);
    };
    std::printf("%zu lines: window %ld kB %.2f s (%s); whole %ld kB %.2f s (%s)\n", n, w.max_rss_kb, w.seconds,
                first_path(w.out).c_str(), h.max_rss_kb, h.seconds, first_path(h.out).c_str());
    std::remove(file.c_str());
    if (smallest == 0) smallest = w.max_rss_kb;
    else EXPECT_LE(w.max_rss_kb, smallest * 6 / 5 + 16 * 1024) << n << " lines";
  }
}

}  // namespace
