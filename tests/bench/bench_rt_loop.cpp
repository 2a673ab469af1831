// Wake-up jitter of hal::RtLoop on this machine: the real loop at 1 ms for
// 2 s (after rt_setup(80, true), whose warning is printed if it was refused),
// then the stats line and the histogram. A figure for the notes; it asserts
// nothing (machines are noisy).
//
// usage: kerf_bench_rt_loop [--period-ms P] [--seconds S] [--priority N]
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "kerf/hal/rt_loop.hpp"

int main(int argc, char** argv) {
  double period_ms = 1.0, seconds = 2.0;
  int priority = 80;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--period-ms") == 0)
      period_ms = std::atof(argv[i + 1]);
    else if (std::strcmp(argv[i], "--seconds") == 0)
      seconds = std::atof(argv[i + 1]);
    else if (std::strcmp(argv[i], "--priority") == 0)
      priority = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "usage: %s [--period-ms P] [--seconds S] [--priority N]\n", argv[0]);
      return 2;
    }
  }
  if (!(period_ms > 0.0) || !(seconds > 0.0)) {
    std::fprintf(stderr, "kerf_bench_rt_loop: period and duration must be > 0\n");
    return 2;
  }
  const kerf::hal::RtSetup setup = kerf::hal::rt_setup(priority, true);
  if (!setup.warning.empty()) std::fprintf(stderr, "%s\n", setup.warning.c_str());
  std::printf("rt_loop: period %.3f ms for %.1f s, SCHED_FIFO %s, memory %s\n", period_ms, seconds,
              setup.fifo ? "yes" : "no", setup.locked ? "locked" : "not locked");
  kerf::hal::RtLoop loop(period_ms * 1e-3);
  const double end = kerf::hal::monotonic_s() + seconds;
  while (loop.wait_next() < end) {
  }
  std::printf("%s\n%s", loop.stats().describe().c_str(), loop.stats().histogram().c_str());
  return 0;
}
