#include "weld_pipe.hpp"

#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

namespace kerf_test {

void append_shape(std::string& out, std::uint64_t k) {
  const double cx = 20.0 * static_cast<double>(k % 50), cy = 20.0 * static_cast<double>((k / 50) % 50);
  constexpr int kPoints = 24;
  constexpr int kDots = static_cast<int>(kShapeLines) - kPoints - 4;
  constexpr double kPi = 3.14159265358979323846;
  char line[96];
  auto put = [&](int n) { out.append(line, static_cast<std::size_t>(n)); };
  put(std::snprintf(line, sizeof line, "G0 X%.3f Y%.3f\nM3\n", cx + 1, cy));
  for (int i = 1; i <= kPoints; ++i) {
    const double a = 2 * kPi * i / kPoints;
    put(std::snprintf(line, sizeof line, i == 1 ? "G1 X%.3f Y%.3f F1200\n" : "G1 X%.3f Y%.3f\n",
                      cx + std::cos(a), cy + std::sin(a)));
  }
  put(std::snprintf(line, sizeof line, "M5\n(shape %llu)\n", static_cast<unsigned long long>(k)));
  for (int i = 0; i < kDots; ++i)  // rapids over a row of dots: lines kerf passes through
    put(std::snprintf(line, sizeof line, "G0 X%.3f Y%.3f\n", cx + 0.05 * i, cy - 2));
}

namespace {

bool write_all(int fd, const std::string& s) {
  for (std::size_t off = 0; off < s.size();) {
    const ssize_t w = write(fd, s.data() + off, s.size() - off);
    if (w <= 0) return false;
    off += static_cast<std::size_t>(w);
  }
  return true;
}

}  // namespace

PipeRun weld_pipe(const std::string& kerf, std::uint64_t lines, int threads, bool keep_output) {
  PipeRun r;
  int in[2], out[2], err[2];
  if (pipe(in) != 0 || pipe(out) != 0 || pipe(err) != 0) return r;
  const std::string t = std::to_string(threads);
  const auto t0 = std::chrono::steady_clock::now();
  auto since = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  const pid_t pid = fork();
  if (pid < 0) return r;
  if (pid == 0) {
    dup2(in[0], 0);
    dup2(out[1], 1);
    dup2(err[1], 2);
    for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]}) close(fd);
    execl(kerf.c_str(), kerf.c_str(), "weld", "--tol", "0.025", "--threads", t.c_str(), "-", "-",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  close(in[0]);
  close(out[1]);
  close(err[1]);
  std::thread writer([&] {
    std::string buf;
    std::uint64_t k = 0;
    while (r.lines < lines) {
      buf.clear();
      for (int i = 0; i < 2000 && r.lines < lines; ++i, ++k, r.lines += kShapeLines) append_shape(buf, k);
      if (!write_all(in[1], buf)) break;
    }
    close(in[1]);
    r.input_written = since();
  });
  char buf[1 << 16];
  pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
  int open_fds = 2;
  while (open_fds > 0) {
    if (poll(fds, 2, -1) < 0) break;
    for (pollfd& p : fds) {
      if (p.fd < 0 || p.revents == 0) continue;
      const ssize_t n = read(p.fd, buf, sizeof buf);
      if (n <= 0) {
        close(p.fd);
        p.fd = -1;
        --open_fds;
        continue;
      }
      const auto got = static_cast<std::size_t>(n);
      if (p.fd == out[0]) {
        if (r.out_bytes == 0) r.first_output = since();
        r.out_bytes += got;
        if (keep_output) r.out.append(buf, got);
      } else {
        r.err.append(buf, got);
      }
    }
  }
  writer.join();
  int status = 0;
  rusage ru{};
  if (wait4(pid, &status, 0, &ru) != pid) return r;
  r.seconds = since();
  r.max_rss_kb = ru.ru_maxrss;
  r.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return r;
}

}  // namespace kerf_test
