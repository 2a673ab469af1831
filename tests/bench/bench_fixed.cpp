// kerf::Fixed against double: the vertex, band and biarc fits of the sine curve and
// the interpolator's step, each timed in both scalar types (best of a few
// runs), and the fixed/double ratio printed.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "bench_util.hpp"
#include "kerf/core/fixed_convert.hpp"
#include "kerf/fit/band.hpp"
#include "kerf/fit/biarc.hpp"
#include "kerf/fit/biarc/tangent.hpp"
#include "kerf/fit/fit.hpp"
#include "kerf/motion/interpolator.hpp"

namespace {

using Clock = std::chrono::steady_clock;

template <class S>
S from_d(double v) {
  if constexpr (__is_same(S, kerf::Fixed)) return kerf::fixed_from_double(v);
  else return v;
}

template <class S>
struct Fitted {
  std::vector<kerf::fit::Piece<S>> pieces;
  std::uint32_t count = 0;
  double best_ms = 1e300;
};

template <class S>
Fitted<S> time_fit(const std::vector<kerf::Vec2<double>>& pd, double tol, int runs) {
  const std::size_t n = pd.size();
  std::vector<kerf::Vec2<S>> p(n);
  for (std::size_t k = 0; k < n; ++k) p[k] = {from_d<S>(pd[k].x), from_d<S>(pd[k].y)};
  std::vector<std::uint32_t> words(kerf::fit::workspace_words(n));
  std::vector<kerf::fit::Interval<S>> iv(kerf::fit::workspace_intervals(n));
  std::vector<kerf::Vec2<S>> scaled(n);
  Fitted<S> out;
  out.pieces.resize(n);
  for (int r = 0; r < runs; ++r) {
    const auto t0 = Clock::now();
    const auto res = kerf::fit::fit_min_count<S>(
        {p.data(), n}, from_d<S>(tol), kerf::fit::Method::optimal,
        {{words.data(), words.size()}, {iv.data(), iv.size()}, {scaled.data(), n}},
        {out.pieces.data(), n});
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    out.best_ms = std::min(out.best_ms, ms);
    out.count = res.ok() ? res.value().pieces : 0;
  }
  return out;
}

// The band fit (min count, with its tie-break bisection) at tol on both sides.
template <class S>
Fitted<S> time_band(const std::vector<kerf::Vec2<double>>& pd, double tol, int runs) {
  const std::size_t n = pd.size();
  std::vector<kerf::Vec2<S>> p(n);
  for (std::size_t k = 0; k < n; ++k) p[k] = {from_d<S>(pd[k].x), from_d<S>(pd[k].y)};
  const std::vector<kerf::fit::BandWidth<S>> w(n, {from_d<S>(tol), from_d<S>(tol)});
  std::vector<std::uint32_t> words(kerf::fit::band_workspace_words(n));
  std::vector<kerf::Vec2<S>> scaled(n);
  std::vector<kerf::fit::BandVertex<S>> vertices(n);
  Fitted<S> out;
  out.pieces.resize(n);
  for (int r = 0; r < runs; ++r) {
    const auto t0 = Clock::now();
    const auto res = kerf::fit::fit_band_min_count<S>(
        {p.data(), n}, {w.data(), n},
        {{words.data(), words.size()}, {scaled.data(), n}, {vertices.data(), n}},
        {out.pieces.data(), n});
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    out.best_ms = std::min(out.best_ms, ms);
    out.count = res.ok() ? res.value().pieces : 0;
  }
  return out;
}

// The biarc fit (fewest biarcs, exact joint sets) at tol on both sides, on
// tangents estimated in the type (counted in the time).
template <class S>
Fitted<S> time_biarc(const std::vector<kerf::Vec2<double>>& pd, double tol, int runs) {
  const std::size_t n = pd.size();
  std::vector<kerf::Vec2<S>> p(n);
  for (std::size_t k = 0; k < n; ++k) p[k] = {from_d<S>(pd[k].x), from_d<S>(pd[k].y)};
  const std::vector<kerf::fit::BandWidth<S>> w(n, {from_d<S>(tol), from_d<S>(tol)});
  std::vector<kerf::Vec2<S>> t(n);
  std::vector<std::uint32_t> words(kerf::fit::biarc_workspace_words(n));
  std::vector<kerf::Vec2<S>> scaled(n);
  std::vector<kerf::fit::BandVertex<S>> vertices(n);
  std::vector<kerf::fit::BiarcPiece<S>> pieces(n);
  Fitted<S> out;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = Clock::now();
    kerf::fit::estimate_tangents<S>({p.data(), n}, {t.data(), n});
    const auto res = kerf::fit::fit_biarc_min_count<S>(
        {p.data(), n}, {t.data(), n}, {w.data(), n}, {},
        {{words.data(), words.size()}, {vertices.data(), n}, {scaled.data(), n}}, {pieces.data(), n});
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    out.best_ms = std::min(out.best_ms, ms);
    out.count = res.ok() ? res.value().pieces : 0;
  }
  return out;
}

// ns per interpolator step over the fitted path at 100 mm/s, 1 ms period.
template <class S>
double time_steps(const Fitted<S>& f, long& steps) {
  std::vector<kerf::motion::QueuedSegment<S>> slots(f.count);
  kerf::motion::Interpolator<S> ip({slots.data(), slots.size()});
  kerf::motion::MotionConfig<S> cfg;
  cfg.period = from_d<S>(0.001);
  cfg.accel = from_d<S>(1000.0);
  cfg.corner_angle = from_d<S>(0.1);
  if (ip.configure(cfg) != kerf::Status::ok) return -1;
  for (std::uint32_t k = 0; k < f.count; ++k)
    if (ip.push({f.pieces[k].segment, from_d<S>(100.0), k + 1}) != kerf::Status::ok) return -1;
  steps = 0;
  const auto t0 = Clock::now();
  while (ip.step().state != kerf::motion::MotionState::done && steps < 10000000) ++steps;
  return std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / static_cast<double>(steps);
}

}  // namespace

int main() {
  const auto pd = kerf_bench::sine(400, 1.0);
  const double tol = 0.05;
  const auto fd = time_fit<double>(pd, tol, 5);
  const auto ff = time_fit<kerf::Fixed>(pd, tol, 3);
  std::printf("fit sine n=400 tol %.2f: double %u pieces %.3f ms, fixed %u pieces %.3f ms, ratio %.1f\n",
              tol, fd.count, fd.best_ms, ff.count, ff.best_ms, ff.best_ms / fd.best_ms);
  const auto bd = time_band<double>(pd, tol, 5);
  const auto bf = time_band<kerf::Fixed>(pd, tol, 3);
  std::printf("band fit sine n=400 tol %.2f: double %u pieces %.3f ms, fixed %u pieces %.3f ms, ratio %.1f\n",
              tol, bd.count, bd.best_ms, bf.count, bf.best_ms, bf.best_ms / bd.best_ms);
  const auto ad = time_biarc<double>(pd, tol, 3);
  const auto af = time_biarc<kerf::Fixed>(pd, tol, 2);
  std::printf("biarc fit sine n=400 tol %.2f: double %u biarcs %.3f ms, fixed %u biarcs %.3f ms, ratio %.1f\n",
              tol, ad.count, ad.best_ms, af.count, af.best_ms, af.best_ms / ad.best_ms);
  long sd = 0, sf = 0;
  double nd = 1e300, nf = 1e300;
  for (int r = 0; r < 3; ++r) {
    nd = std::min(nd, time_steps(fd, sd));
    nf = std::min(nf, time_steps(ff, sf));
  }
  std::printf("interpolate: double %ld steps %.1f ns/step, fixed %ld steps %.1f ns/step, ratio %.1f\n",
              sd, nd, sf, nf, nf / nd);
  return fd.count == ff.count && bd.count == bf.count && ad.count == af.count && ad.count > 0 ? 0 : 1;
}
