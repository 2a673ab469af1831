// The jitter histogram and its summary: pure arithmetic, tested on synthetic data.
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>

#include "kerf/hal/rt_loop.hpp"

namespace kerf::hal {

std::size_t jitter_bin(double late_s) {
  const double us = late_s * 1e6;
  constexpr std::size_t last = kJitterBins - 1;
  if (!(us >= 1.0)) return 0;  // also negative and NaN
  if (us >= std::ldexp(1.0, static_cast<int>(last))) return last;
  // us in [2^(k-1), 2^k) has bit width k.
  return static_cast<std::size_t>(std::bit_width(static_cast<std::uint64_t>(us)));
}

double jitter_bin_upper_us(std::size_t bin) {
  if (bin >= kJitterBins - 1) return std::numeric_limits<double>::infinity();
  return std::ldexp(1.0, static_cast<int>(bin));
}

double jitter_percentile_us(const RtStats& stats, double q) {
  std::uint64_t total = 0;
  for (const std::uint64_t n : stats.jitter) total += n;
  if (total == 0) return 0.0;
  const double want = std::ceil(q * static_cast<double>(total));
  const std::uint64_t target = want < 1.0 ? 1 : static_cast<std::uint64_t>(want);
  const double max_us = stats.max_late_s * 1e6;
  std::uint64_t seen = 0;
  for (std::size_t k = 0; k < kJitterBins; ++k) {
    seen += stats.jitter[k];
    if (seen >= target) return std::fmin(jitter_bin_upper_us(k), max_us);
  }
  return max_us;
}

void RtStats::record(double late_s) {
  if (!(late_s > 0.0)) late_s = 0.0;
  ++cycles;
  ++jitter[jitter_bin(late_s)];
  if (late_s > max_late_s) max_late_s = late_s;
}

std::string RtStats::describe() const {
  char b[160];
  if (cycles == 0) {
    std::snprintf(b, sizeof b, "cycles 0, overruns %llu",
                  static_cast<unsigned long long>(overruns));
  } else {
    std::snprintf(
        b, sizeof b, "cycles %llu, overruns %llu, late p50 %.0f us, p99 %.0f us, max %.0f us",
        static_cast<unsigned long long>(cycles), static_cast<unsigned long long>(overruns),
        jitter_percentile_us(*this, 0.50), jitter_percentile_us(*this, 0.99), max_late_s * 1e6);
  }
  return b;
}

std::string RtStats::histogram() const {
  std::string out;
  for (std::size_t k = 0; k < kJitterBins; ++k) {
    if (jitter[k] == 0) continue;
    char b[80];
    const double lo = k == 0 ? 0.0 : std::ldexp(1.0, static_cast<int>(k) - 1);
    if (k == kJitterBins - 1)
      std::snprintf(b, sizeof b, "[%.0f, inf) us %12llu\n", lo,
                    static_cast<unsigned long long>(jitter[k]));
    else
      std::snprintf(b, sizeof b, "[%.0f, %.0f) us %12llu\n", lo, jitter_bin_upper_us(k),
                    static_cast<unsigned long long>(jitter[k]));
    out += b;
  }
  return out;
}

}  // namespace kerf::hal
