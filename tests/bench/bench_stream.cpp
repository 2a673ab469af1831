// Peak RSS of `kerf fit --stream` at 1e5 and 1e7 points, in one run: the
// streamed fit must use the same memory for any input length.
//
//   kerf_bench_stream [KERF] [--small N] [--large N] [--window N] [--tol EPS]
//
// Each run forks kerf, writes the points into its stdin through a pipe as it
// reads them (a long wavy line with a little noise: pieces of about 50
// points at tol 0.01), sends its output to /dev/null, and takes kerf's peak
// RSS from wait4(). Prints each run's RSS and time, and the ratio of the
// RSS figures. Exit 1 when a run fails or the RSS differs by more than 5%.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

struct Run {
  bool ok = false;
  long rss_kb = 0;
  double seconds = 0;
};

// Writes n points of y = 10 sin(x / 10) + noise (+-0.001), x = 0.1 k.
bool write_points(int fd, std::uint64_t n) {
  std::uint32_t seed = 12345;
  char buf[1 << 16];
  std::size_t used = 0;
  for (std::uint64_t k = 0; k < n; ++k) {
    seed = seed * 1103515245u + 12345u;
    const double x = 0.1 * static_cast<double>(k);
    const double noise = (static_cast<double>(seed >> 8) / 16777216.0 - 0.5) * 0.002;
    used += static_cast<std::size_t>(
        std::snprintf(buf + used, sizeof buf - used, "%.6f %.6f\n", x, 10 * std::sin(x / 10) + noise));
    if (used > sizeof buf - 64 || k + 1 == n) {
      for (std::size_t off = 0; off < used;) {
        const ssize_t w = write(fd, buf + off, used - off);
        if (w <= 0) return false;
        off += static_cast<std::size_t>(w);
      }
      used = 0;
    }
  }
  return true;
}

Run run(const char* kerf, std::uint64_t n, const std::string& window, const std::string& tol) {
  Run r;
  int in[2];
  if (pipe(in) != 0) return r;
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) return r;
  if (pid == 0) {
    dup2(in[0], 0);
    close(in[0]);
    close(in[1]);
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    execl(kerf, kerf, "fit", "--stream", "--window", window.c_str(), "--tol", tol.c_str(), "-",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  close(in[0]);
  const bool written = write_points(in[1], n);
  close(in[1]);
  int status = 0;
  rusage use{};
  if (wait4(pid, &status, 0, &use) != pid) return r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.rss_kb = use.ru_maxrss;  // kilobytes on Linux
  r.ok = written && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const char* kerf = KERF_BIN;
  std::uint64_t small = 100000;
  std::uint64_t large = 10000000;
  std::string window = "1024";
  std::string tol = "0.01";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--small" && has_value) small = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--large" && has_value) large = std::strtoull(argv[++i], nullptr, 10);
    else if (a == "--window" && has_value) window = argv[++i];
    else if (a == "--tol" && has_value) tol = argv[++i];
    else if (a[0] != '-') kerf = argv[i];
    else {
      std::fprintf(stderr, "usage: %s [KERF] [--small N] [--large N] [--window N] [--tol EPS]\n",
                   argv[0]);
      return 2;
    }
  }
  std::printf("kerf fit --stream --window %s --tol %s (%s)\n", window.c_str(), tol.c_str(), kerf);
  const Run a = run(kerf, small, window, tol);
  std::printf("%12llu points: peak RSS %7ld KiB, %8.2f s%s\n", static_cast<unsigned long long>(small),
              a.rss_kb, a.seconds, a.ok ? "" : "  FAILED");
  std::fflush(stdout);
  const Run b = run(kerf, large, window, tol);
  std::printf("%12llu points: peak RSS %7ld KiB, %8.2f s%s\n", static_cast<unsigned long long>(large),
              b.rss_kb, b.seconds, b.ok ? "" : "  FAILED");
  if (!a.ok || !b.ok || a.rss_kb <= 0) return 1;
  const double ratio = static_cast<double>(b.rss_kb) / static_cast<double>(a.rss_kb);
  std::printf("RSS ratio (large / small): %.4f\n", ratio);
  return std::fabs(ratio - 1.0) <= 0.05 ? 0 : 1;
}
