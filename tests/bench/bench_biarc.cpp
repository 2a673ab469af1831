// Throughput (points per second) and memory of the biarc fitter against n,
// on the sine wave of bench_fit, with estimated tangents; the growth
// exponent; and, up to --exact-max-n, every pair tested (BiarcOptions::exact)
// against the default, which skips the pairs the proven reach bound of
// fit/biarc/reach.hpp rules out (same counts, by the bound's proof). Prints figures measured in this run; it
// asserts nothing about speed.
//
// Memory: the caller-provided storage core uses (2n words, n region
// vertices, n - 1 biarc slots, n tangents) is exact; the process's peak
// resident size (getrusage) is printed after each n for the whole run.
//
// usage: kerf_bench_biarc [--max-n N] [--exact-max-n N] [--repeat R] [--tol T] [--dx D]
//                         [--method sets|paper]
#include <sys/resource.h>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "bench_util.hpp"
#include "biarc_visibility.hpp"
#include "io/biarc_storage.hpp"
#include "kerf/fit/biarc.hpp"

namespace {

using kerf::Vec2;
namespace fit = kerf::fit;

// --method paper: the pair test of tests/support/biarc_visibility.hpp instead
// of the exact joint sets.
fit::BiarcJointsFn g_joints = nullptr;

struct Run {
  std::uint32_t biarcs = 0;
  double seconds = 1e300;
};

Run once(const std::vector<Vec2<double>>& p, double tol, bool exact) {
  const std::size_t n = p.size();
  const std::clock_t t0 = std::clock();  // CPU time: the machine is shared
  const std::vector<Vec2<double>> t = kerf::io::estimated_tangents(p);
  std::vector<fit::BandWidth<double>> widths(n, {tol, tol});
  kerf::io::BiarcStorage s(n);
  fit::BiarcOptions opts;
  opts.exact = exact;
  opts.joints = g_joints;
  const auto r = fit::fit_biarc_min_count<double>({p.data(), n}, {t.data(), n}, {widths.data(), n},
                                                  opts, s.workspace(), s.pieces());
  const std::clock_t t1 = std::clock();
  if (!r.ok()) {
    std::fprintf(stderr, "fit failed: %s\n", kerf::to_string(r.status()));
    std::exit(1);
  }
  return {r.value().pieces, static_cast<double>(t1 - t0) / CLOCKS_PER_SEC};
}

Run best_of(const std::vector<Vec2<double>>& p, double tol, bool exact, int repeat) {
  Run best;
  for (int r = 0; r < repeat; ++r) {
    const Run x = once(p, tol, exact);
    best = {x.biarcs, std::min(best.seconds, x.seconds)};
  }
  return best;
}

std::size_t storage_bytes(std::size_t n) {
  return fit::biarc_workspace_words(n) * sizeof(std::uint32_t) + n * sizeof(fit::BandVertex<double>) +
         (n - 1) * sizeof(fit::BiarcPiece<double>) + 2 * n * sizeof(Vec2<double>);
}

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux: KiB
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t max_n = 16000;
  std::size_t exact_max_n = 2000;
  int repeat = 3;
  double tol = 0.01;
  double dx = 0.5;
  for (int a = 1; a + 1 < argc; a += 2) {
    if (!std::strcmp(argv[a], "--max-n")) max_n = std::strtoul(argv[a + 1], nullptr, 10);
    if (!std::strcmp(argv[a], "--exact-max-n")) exact_max_n = std::strtoul(argv[a + 1], nullptr, 10);
    if (!std::strcmp(argv[a], "--repeat")) repeat = std::atoi(argv[a + 1]);
    if (!std::strcmp(argv[a], "--tol")) tol = std::atof(argv[a + 1]);
    if (!std::strcmp(argv[a], "--dx")) dx = std::atof(argv[a + 1]);
    if (!std::strcmp(argv[a], "--method") && !std::strcmp(argv[a + 1], "paper"))
      g_joints = fit::biarc_paper_joints;
  }
  std::printf("biarc fitter (%s pair test), symmetric tol %g on y = %g sin(2 pi x / %g), dx = %g, "
              "estimated tangents\n",
              g_joints != nullptr ? "paper" : "exact-sets", tol,
              kerf_bench::kAmplitude, kerf_bench::kPeriod, dx);
  std::printf("%8s %8s %8s %12s %14s %12s %12s %10s\n", "n", "biarcs", "span", "pt/s",
              "all-pair pt/s", "a.p. biarcs", "storage KiB", "peak MiB");
  std::vector<double> ns, ts;
  for (std::size_t n = 250; n <= max_n; n *= 2) {
    const auto p = kerf_bench::sine(n, dx);
    const int rep = n >= 4000 ? 1 : repeat;
    const Run d = best_of(p, tol, false, rep);
    const bool exact = n <= exact_max_n;
    const Run e = exact ? best_of(p, tol, true, 1) : Run{};
    const double nd = static_cast<double>(n);
    std::printf("%8zu %8u %8.1f %12.0f %14.1f %12u %12.1f %10.1f\n", n, d.biarcs,
                (nd - 1) / d.biarcs, nd / d.seconds, exact ? nd / e.seconds : 0.0,
                exact ? e.biarcs : 0u, static_cast<double>(storage_bytes(n)) / 1024.0,
                peak_rss_mib());
    std::fflush(stdout);
    ns.push_back(nd);
    ts.push_back(d.seconds);
  }
  if (ns.size() >= 2)
    std::printf("growth exponent of the default fit (least squares over n): %.3f\n",
                kerf_bench::growth_exponent(ns, ts));
  std::printf("pt/s is the whole fit (tangents, exact joint sets, joints, certified error); "
              "all-pair tests every pair, without the proven reach bound. Times are CPU time.\n");
  return 0;
}
