// hal::RtLoop: histogram and percentiles on synthetic data, deadline and
// overrun accounting on a fake clock, rt_setup with and without privileges,
// and the real clock's deadlines (spacing only, never durations).
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <string>

#include "kerf/hal/rt_loop.hpp"

namespace {

using namespace kerf::hal;

TEST(RtStats, BinsFollowPowersOfTwoMicroseconds) {
  EXPECT_EQ(jitter_bin(0.0), 0u);
  EXPECT_EQ(jitter_bin(-5e-6), 0u);
  EXPECT_EQ(jitter_bin(0.999e-6), 0u);
  EXPECT_EQ(jitter_bin(1e-6), 1u);  // [1, 2)
  EXPECT_EQ(jitter_bin(1.9e-6), 1u);
  EXPECT_EQ(jitter_bin(2e-6), 2u);   // [2, 4)
  EXPECT_EQ(jitter_bin(12e-6), 4u);  // [8, 16)
  EXPECT_EQ(jitter_bin(16e-6), 5u);
  EXPECT_EQ(jitter_bin(16383e-6), 14u);  // [8192, 16384)
  EXPECT_EQ(jitter_bin(16384e-6), kJitterBins - 1);
  EXPECT_EQ(jitter_bin(10.0), kJitterBins - 1);
  EXPECT_EQ(jitter_bin_upper_us(0), 1.0);
  EXPECT_EQ(jitter_bin_upper_us(4), 16.0);
  EXPECT_TRUE(std::isinf(jitter_bin_upper_us(kJitterBins - 1)));
}

TEST(RtStats, PercentilesAreBinUpperBoundsCappedAtTheMax) {
  RtStats s;
  for (int i = 0; i < 90; ++i) s.record(10e-6);  // [8, 16)
  for (int i = 0; i < 9; ++i) s.record(50e-6);   // [32, 64)
  s.record(140e-6);                              // [128, 256), the max
  EXPECT_EQ(s.cycles, 100u);
  EXPECT_EQ(s.jitter[4], 90u);
  EXPECT_EQ(s.jitter[6], 9u);
  EXPECT_EQ(s.jitter[8], 1u);
  EXPECT_EQ(jitter_percentile_us(s, 0.50), 16.0);
  EXPECT_EQ(jitter_percentile_us(s, 0.90), 16.0);
  EXPECT_EQ(jitter_percentile_us(s, 0.91), 64.0);
  EXPECT_EQ(jitter_percentile_us(s, 0.99), 64.0);
  EXPECT_NEAR(jitter_percentile_us(s, 1.0), 140.0, 1e-9);  // 256 capped at the max
  EXPECT_EQ(s.describe(), "cycles 100, overruns 0, late p50 16 us, p99 64 us, max 140 us");
  EXPECT_EQ(s.histogram(),
            "[8, 16) us           90\n[32, 64) us            9\n[128, 256) us            1\n");
}

TEST(RtStats, LastBinTakesEverythingAboveAndEmptyStatsSayLittle) {
  RtStats s;
  EXPECT_EQ(jitter_percentile_us(s, 0.5), 0.0);
  EXPECT_EQ(s.describe(), "cycles 0, overruns 0");
  s.record(0.5);  // half a second late
  EXPECT_EQ(s.jitter[kJitterBins - 1], 1u);
  EXPECT_EQ(s.describe(), "cycles 1, overruns 0, late p50 500000 us, p99 500000 us, max 500000 us");
  EXPECT_EQ(s.histogram(), "[16384, inf) us            1\n");
}

// Time moves only when the loop sleeps (waking `latency_ns` late) or the test works.
class FakeClock final : public RtClock {
 public:
  std::int64_t now = 1'000'000'000;
  std::int64_t latency_ns = 0;
  std::int64_t last_deadline = 0;
  std::int64_t now_ns() override { return now; }
  void sleep_until_ns(std::int64_t deadline_ns) override {
    last_deadline = deadline_ns;
    if (deadline_ns > now) now = deadline_ns;
    now += latency_ns;
  }
};

constexpr std::int64_t kMs = 1'000'000;

TEST(RtLoop, DeadlinesAreAbsoluteSoLatenessDoesNotAccumulate) {
  FakeClock c;
  c.latency_ns = 12'000;  // every wake-up 12 us late
  RtLoop loop(1e-3, c);
  const double t0 = loop.wait_next();
  EXPECT_DOUBLE_EQ(t0, 1.001);
  for (int k = 1; k <= 100; ++k) {
    c.now += 300'000;  // 0.3 ms of work
    const double t = loop.wait_next();
    EXPECT_EQ(c.last_deadline, 1'001 * kMs + k * kMs);  // not shifted by the 12 us
    EXPECT_NEAR(t - t0, k * 1e-3, 1e-9);
  }
  EXPECT_EQ(loop.stats().cycles, 101u);
  EXPECT_EQ(loop.stats().overruns, 0u);
  EXPECT_EQ(loop.stats().jitter[4], 101u);  // 12 us: [8, 16)
  EXPECT_NEAR(loop.stats().max_late_s, 12e-6, 1e-12);
}

TEST(RtLoop, OverrunsSkipMissedDeadlinesAndCountEach) {
  FakeClock c;
  RtLoop loop(1e-3, c);
  loop.wait_next();            // due at 1001 ms
  c.now += 3 * kMs + kMs / 2;  // work until 1004.5 ms: 1002, 1003 and 1004 missed
  loop.wait_next();
  EXPECT_EQ(c.last_deadline, 1005 * kMs);
  EXPECT_EQ(loop.stats().overruns, 3u);
  c.now += kMs;  // work exactly to the next deadline: due now, not missed
  loop.wait_next();
  EXPECT_EQ(c.last_deadline, 1006 * kMs);
  EXPECT_EQ(loop.stats().overruns, 3u);
  c.now += kMs + 1;  // one nanosecond past the next one
  loop.wait_next();
  EXPECT_EQ(c.last_deadline, 1008 * kMs);
  EXPECT_EQ(loop.stats().overruns, 4u);
  EXPECT_EQ(loop.stats().cycles, 4u);
  EXPECT_NE(loop.stats().describe().find("overruns 4"), std::string::npos);
}

TEST(RtLoop, RealClockDeadlinesAreSpacedByWholePeriods) {
  RtLoop loop(1e-3);
  double prev = loop.wait_next();
  EXPECT_LE(prev, monotonic_s());
  std::uint64_t skipped = 0;
  for (int k = 0; k < 20; ++k) {
    const double t = loop.wait_next();
    EXPECT_LE(t, monotonic_s());  // never returns before it is due
    const double periods = (t - prev) / 1e-3;
    EXPECT_GE(periods, 1.0 - 1e-6);
    EXPECT_NEAR(periods, std::round(periods), 1e-5);  // a noisy machine may skip some
    skipped += static_cast<std::uint64_t>(std::llround(periods)) - 1;
    prev = t;
  }
  EXPECT_EQ(loop.stats().overruns, skipped);
  EXPECT_EQ(loop.stats().cycles, 21u);
}

// rt_setup in a child process, so that SCHED_FIFO and mlockall never reach
// the test runner. `unprivileged`: drop to nobody with no memlock allowance first.
struct SetupOutcome {
  bool fifo = false;
  bool locked = false;
  int policy = -1;
  char warning[600] = {};
};

SetupOutcome setup_in_child(bool unprivileged) {
  SetupOutcome out;
  int fds[2];
  if (::pipe(fds) != 0) return out;
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    if (unprivileged) {
      const rlimit none{0, 0};
      ::setrlimit(RLIMIT_MEMLOCK, &none);
      ::setrlimit(RLIMIT_RTPRIO, &none);
      if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(3);
    }
    const RtSetup r = rt_setup(80, true);
    SetupOutcome o;
    o.fifo = r.fifo;
    o.locked = r.locked;
    o.policy = ::sched_getscheduler(0);
    std::strncpy(o.warning, r.warning.c_str(), sizeof o.warning - 1);
    ::_exit(::write(fds[1], &o, sizeof o) == sizeof o ? 0 : 2);
  }
  ::close(fds[1]);
  if (::read(fds[0], &out, sizeof out) != sizeof out) out.policy = -2;
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return out;
}

TEST(RtSetup, UnprivilegedWarnsAndCarriesOn) {
  const SetupOutcome o = setup_in_child(true);
  ASSERT_NE(o.policy, -2) << "the child did not report";
  EXPECT_FALSE(o.fifo);
  EXPECT_FALSE(o.locked);
  EXPECT_EQ(o.policy, SCHED_OTHER);
  const std::string w = o.warning;
  EXPECT_NE(w.find("rt: SCHED_FIFO priority 80 not permitted (EPERM): running with normal "
                   "scheduling; run as root or give the user an rtprio limit (LimitRTPRIO="),
            std::string::npos)
      << w;
  EXPECT_NE(w.find("rt: mlockall"), std::string::npos) << w;
}

TEST(RtSetup,
     AsRunOutcomeIsCoherent) {  // granted (root) or refused: the report matches the process
  const SetupOutcome o = setup_in_child(false);
  ASSERT_NE(o.policy, -2) << "the child did not report";
  EXPECT_EQ(o.fifo, o.policy == SCHED_FIFO);
  const std::string w = o.warning;
  EXPECT_EQ(o.fifo, w.find("SCHED_FIFO") == std::string::npos) << w;
  EXPECT_EQ(o.locked, w.find("mlockall") == std::string::npos) << w;
  EXPECT_EQ(w.empty(), o.fifo && o.locked) << w;
}

TEST(RtSetup, NothingAskedNothingDone) {
  const RtSetup r = rt_setup(0, false);
  EXPECT_FALSE(r.fifo);
  EXPECT_FALSE(r.locked);
  EXPECT_TRUE(r.warning.empty());
}

}  // namespace
