// Throughput of the band fitter (points per second) against n, on the sine
// wave of bench_fit resampled so that one band arc spans about 50 points,
// the growth exponent, and the band / vertex time ratio on the same points.
// Prints figures measured in this run; it asserts nothing about speed.
//
// usage: kerf_bench_band [--max-n N] [--repeat R] [--span S]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "bench_util.hpp"
#include "io/band_storage.hpp"
#include "io/fit_storage.hpp"
#include "kerf/fit/band.hpp"
#include "kerf/fit/fit.hpp"

namespace {

using kerf::Vec2;
namespace fit = kerf::fit;

constexpr double kTol = 0.01;

enum class What { band_search, band_fit, vertex_search };

struct Run {
  std::uint32_t pieces = 0;
  double seconds = 1e300;
};

Run once(const std::vector<Vec2<double>>& p, What what) {
  const std::size_t n = p.size();
  const kerf::Span<const Vec2<double>> pts(p.data(), n);
  std::vector<fit::BandWidth<double>> widths(n, {kTol, kTol});
  const kerf::Span<const fit::BandWidth<double>> w(widths.data(), n);
  kerf::Result<std::uint32_t> count = kerf::Status::invalid_argument;
  const auto t0 = std::chrono::steady_clock::now();
  if (what == What::vertex_search) {
    kerf::io::FitStorage s(n);
    count = fit::count_min<double>(pts, kTol, fit::Method::optimal, s.workspace());
  } else {
    kerf::io::BandStorage s(n);
    if (what == What::band_search) {
      count = fit::count_band_min<double>(pts, w, s.workspace());
    } else {
      const auto r = fit::fit_band_min_count<double>(pts, w, s.workspace(), s.pieces());
      count = r.ok() ? kerf::Result<std::uint32_t>(r.value().pieces) : r.status();
    }
  }
  const auto t1 = std::chrono::steady_clock::now();
  if (!count.ok()) {
    std::fprintf(stderr, "fit failed: %s\n", kerf::to_string(count.status()));
    std::exit(1);
  }
  return {count.value(), std::chrono::duration<double>(t1 - t0).count()};
}

Run best_of(const std::vector<Vec2<double>>& p, What what, int repeat) {
  Run best;
  for (int r = 0; r < repeat; ++r) {
    const Run x = once(p, what);
    best = {x.pieces, std::min(best.seconds, x.seconds)};
  }
  return best;
}

// The spacing at which band arcs span about `span` points.
double spacing_for_span(double span) {
  double dx = 0.5;
  for (int it = 0; it < 6; ++it) {
    const std::size_t n = static_cast<std::size_t>(40 * span);
    const Run r = once(kerf_bench::sine(n, dx), What::band_search);
    dx *= static_cast<double>(n - 1) / r.pieces / span;
  }
  return dx;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t max_n = 1000000;
  int repeat = 3;
  double span = 50;
  for (int a = 1; a + 1 < argc; a += 2) {
    if (!std::strcmp(argv[a], "--max-n")) max_n = std::strtoul(argv[a + 1], nullptr, 10);
    if (!std::strcmp(argv[a], "--repeat")) repeat = std::atoi(argv[a + 1]);
    if (!std::strcmp(argv[a], "--span")) span = std::atof(argv[a + 1]);
  }
  const double dx = spacing_for_span(span);
  std::printf("band fitter, symmetric tol %g on y = %g sin(2 pi x / %g), dx = %.6g "
              "(target span %.0f points per arc)\n",
              kTol, kerf_bench::kAmplitude, kerf_bench::kPeriod, dx, span);
  std::printf("%10s %8s %8s %12s %12s %12s %12s %9s\n", "n", "pieces", "span", "search pt/s",
              "fit pt/s", "vertex pt/s", "v. pieces", "band/vtx");
  std::vector<double> ns, ts;
  for (std::size_t n = 1000; n <= max_n; n *= 10) {
    const auto p = kerf_bench::sine(n, dx);
    const int rep = n >= 1000000 ? 1 : repeat;
    const Run s = best_of(p, What::band_search, rep);
    const Run v = best_of(p, What::vertex_search, rep);
    const bool whole = n <= 100000;
    const Run f = whole ? best_of(p, What::band_fit, rep) : Run{};
    const double nd = static_cast<double>(n);
    std::printf("%10zu %8u %8.1f %12.0f %12.0f %12.0f %12u %9.2f\n", n, s.pieces,
                (nd - 1) / s.pieces, nd / s.seconds, whole ? nd / f.seconds : 0.0, nd / v.seconds,
                v.pieces, s.seconds / v.seconds);
    if (s.pieces >= 20) {
      ns.push_back(nd);
      ts.push_back(s.seconds);
    }
  }
  if (ns.size() >= 2)
    std::printf("growth exponent of the search (least squares over n with >= 20 pieces): %.3f\n",
                kerf_bench::growth_exponent(ns, ts));
  std::printf("fit pt/s is the whole fit: count, the smallest-band tie-break (~20 searches), "
              "pieces and their deviation; band/vtx is the search time ratio.\n");
  return 0;
}
