// hal::RtLoop: a periodic loop on absolute deadlines (clock_nanosleep with
// TIMER_ABSTIME on CLOCK_MONOTONIC), so a late cycle never shifts the ones
// after it. It counts overruns and keeps a histogram of the wake-up jitter.
// rt_setup() asks for SCHED_FIFO and mlockall; where that is not permitted it
// says so in a warning and the loop still runs.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace kerf::hal {

struct RtSetup {
  bool fifo = false;    // SCHED_FIFO granted
  bool locked = false;  // mlockall(MCL_CURRENT | MCL_FUTURE) granted
  std::string warning;  // empty when both were granted (or not asked for)
};

// priority 0: do not ask for SCHED_FIFO. lock_memory false: no mlockall.
RtSetup rt_setup(int priority, bool lock_memory);

// Histogram of wake-up lateness: bin 0 is < 1 us, bin k is [2^(k-1), 2^k) us,
// the last bin everything above.
inline constexpr std::size_t kJitterBins = 16;

// The bin a lateness (seconds, negative counts as 0) falls in.
std::size_t jitter_bin(double late_s);
// A bin's upper bound in us (2^k; the last bin has none: +infinity).
double jitter_bin_upper_us(std::size_t bin);

struct RtStats {
  std::uint64_t cycles = 0;
  std::uint64_t overruns = 0;   // cycles whose work ran past the next deadline
  double max_late_s = 0.0;      // worst wake-up lateness
  std::array<std::uint64_t, kJitterBins> jitter{};
  std::string describe() const;  // one line for the status: cycles, overruns, p50/p99/max
  std::string histogram() const;  // one line per non-empty bin: "[8, 16) us  4123"
  void record(double late_s);     // one wake-up: cycles, histogram, max
};

// The q-quantile (0 < q <= 1) of the lateness in us, from the histogram: the
// upper bound of the bin holding it, capped at the max (so "p99 64 us" reads
// "99 % of the wake-ups were under 64 us"). 0 when no cycle was recorded.
double jitter_percentile_us(const RtStats& stats, double q);

// The loop's time source, injectable so that tests drive overruns and
// lateness without sleeping. The default is CLOCK_MONOTONIC and
// clock_nanosleep(TIMER_ABSTIME), retried on EINTR.
class RtClock {
 public:
  virtual ~RtClock() = default;
  virtual std::int64_t now_ns() = 0;
  virtual void sleep_until_ns(std::int64_t deadline_ns) = 0;
};
RtClock& monotonic_clock();

class RtLoop {
 public:
  explicit RtLoop(double period_s, RtClock& clock = monotonic_clock());
  // Sleeps until the next deadline and returns the monotonic time (s) it was
  // due. When the previous cycle overran, it skips the missed deadlines
  // (counting each as an overrun) and returns the next one in the future.
  // The first call waits one period from now.
  double wait_next();
  double period_s() const { return period_s_; }
  const RtStats& stats() const { return stats_; }

 private:
  double period_s_;
  std::int64_t period_ns_;
  RtClock* clock_;
  std::int64_t next_ns_ = 0;  // 0: not started
  RtStats stats_;
};

double monotonic_s();

}  // namespace kerf::hal
