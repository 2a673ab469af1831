// Throughput of the exact vertex fitter (points per second) against n, on a
// sine wave resampled so that one arc spans about 50 or about 500 points, and
// the growth exponent between the sizes. Prints figures measured in this run;
// it asserts nothing about speed (machines are noisy).
//
// usage: kerf_bench_fit [--max-n N] [--repeat R]
// The whole fit (with its ~30 tie-break searches) is measured up to 1e5.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "bench_util.hpp"
#include "io/fit_storage.hpp"
#include "kerf/fit/fit.hpp"

namespace {

using kerf::Vec2;
namespace fit = kerf::fit;

constexpr double kTol = 0.01;
using kerf_bench::kAmplitude;
using kerf_bench::kPeriod;
using kerf_bench::sine;
using kerf_bench::growth_exponent;

struct Run {
  std::uint32_t pieces = 0;
  double seconds = 0;
};

// Best of `repeat` runs of either the bare count (the search) or the whole
// fit: count, tie-break on the smallest max error, and the pieces.
Run measure(const std::vector<Vec2<double>>& p, bool whole_fit, int repeat) {
  kerf::io::FitStorage storage(p.size());
  const fit::Workspace<double> ws = storage.workspace();
  Run best{0, 1e300};
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    kerf::Status status;
    if (whole_fit) {
      const auto res = fit::fit_min_count<double>({p.data(), p.size()}, kTol, fit::Method::optimal,
                                                  ws, storage.pieces());
      status = res.status();
      best.pieces = res.value().pieces;
    } else {
      const auto res = fit::count_min<double>({p.data(), p.size()}, kTol, fit::Method::optimal, ws);
      status = res.status();
      best.pieces = res.value();
    }
    const auto t1 = std::chrono::steady_clock::now();
    if (status != kerf::Status::ok) {
      std::fprintf(stderr, "fit failed: %s\n", kerf::to_string(status));
      std::exit(1);
    }
    best.seconds = std::min(best.seconds, std::chrono::duration<double>(t1 - t0).count());
  }
  return best;
}

void table(const char* title, double span, double dx, std::size_t max_n, bool whole_fit, int repeat) {
  std::printf("\n%s, target span %.0f points per arc (dx = %.6g)\n", title, span, dx);
  std::printf("%10s %8s %10s %12s %14s\n", "n", "pieces", "span", "seconds", "points/s");
  std::vector<double> ns;
  std::vector<double> ts;
  for (std::size_t n = 1000; n <= max_n; n *= 10) {
    const Run r = measure(sine(n, dx), whole_fit, n >= 1000000 ? 1 : repeat);
    const double got_span = static_cast<double>(n - 1) / r.pieces;
    std::printf("%10zu %8u %10.1f %12.6f %14.0f\n", n, r.pieces, got_span, r.seconds,
                static_cast<double>(n) / r.seconds);
    if (r.pieces >= 20) {  // fewer pieces measure the ends of the curve, not the growth
      ns.push_back(static_cast<double>(n));
      ts.push_back(r.seconds);
    }
  }
  if (ns.size() >= 2)
    std::printf("growth exponent (least squares over n with >= 20 pieces): %.3f\n",
                growth_exponent(ns, ts));
}

// The spacing at which arcs span about `span` points: measure on a pilot run.
double spacing_for_span(double span) {
  double dx = 0.5;
  for (int it = 0; it < 6; ++it) {
    const std::size_t n = static_cast<std::size_t>(40 * span);
    const Run r = measure(sine(n, dx), false, 1);
    const double got = static_cast<double>(n - 1) / r.pieces;
    dx *= got / span;
  }
  return dx;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t max_n = 1000000;
  int repeat = 3;
  for (int a = 1; a + 1 < argc; a += 2) {
    if (!std::strcmp(argv[a], "--max-n")) max_n = std::strtoul(argv[a + 1], nullptr, 10);
    if (!std::strcmp(argv[a], "--repeat")) repeat = std::atoi(argv[a + 1]);
  }
  std::printf("vertex fitter, method optimal, tol %g on y = %g sin(2 pi x / %g)\n", kTol,
              kAmplitude, kPeriod);
  for (const double span : {50.0, 500.0}) {
    const double dx = spacing_for_span(span);
    table("fewest-pieces search (count_min)", span, dx, max_n, false, repeat);
    table("whole fit (fit_min_count: count, max-error tie-break, pieces)", span, dx,
          std::min<std::size_t>(max_n, 100000), true, repeat);
  }
  return 0;
}
