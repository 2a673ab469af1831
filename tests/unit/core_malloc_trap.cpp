// The core never allocates, proven at run time: this program replaces malloc,
// calloc, realloc and operator new with a trap that aborts while armed, then
// runs the vertex, band and biarc fitters and the interpolator in double and
// in kerf::Fixed on the report's parabola, all storage static. `--self-check` allocates while
// armed and must die with the trap's message, which shows the trap is live.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

#include "kerf/core/fixed_convert.hpp"
#include "kerf/fit/band.hpp"
#include "kerf/fit/biarc.hpp"
#include "kerf/fit/biarc/tangent.hpp"
#include "kerf/fit/fit.hpp"
#include "kerf/fit/stream.hpp"
#include "kerf/fit/stream_band.hpp"
#include "kerf/motion/interpolator.hpp"

namespace {

volatile bool g_armed = false;

[[noreturn]] void trap(const char* what) {
  const char msg[] = "core_malloc_trap: allocation while armed: ";
  (void)!write(2, msg, sizeof msg - 1);
  (void)!write(2, what, std::strlen(what));
  (void)!write(2, "\n", 1);
  _exit(86);  // no abort(): ctest reads a signal as a crash even when expected
}

}  // namespace

extern "C" {
extern void* __libc_malloc(std::size_t);
extern void* __libc_calloc(std::size_t, std::size_t);
extern void* __libc_realloc(void*, std::size_t);
void* malloc(std::size_t n) {
  if (g_armed) trap("malloc");
  return __libc_malloc(n);
}
void* calloc(std::size_t n, std::size_t m) {
  if (g_armed) trap("calloc");
  return __libc_calloc(n, m);
}
void* realloc(void* p, std::size_t n) {
  if (g_armed) trap("realloc");
  return __libc_realloc(p, n);
}
}
void* operator new(std::size_t n) {
  if (g_armed) trap("operator new");
  return malloc(n == 0 ? 1 : n);
}
void* operator new[](std::size_t n) {
  if (g_armed) trap("operator new[]");
  return malloc(n == 0 ? 1 : n);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace {

constexpr std::size_t kN = 200;

template <class S>
struct FitStatic {
  std::uint32_t words[kerf::fit::workspace_words(kN)];
  kerf::fit::Interval<S> intervals[kerf::fit::workspace_intervals(kN)];
  kerf::Vec2<S> scaled[kN];
  kerf::Vec2<S> points[kN];
  kerf::fit::Piece<S> pieces[kN];
};
FitStatic<double> g_fd;
FitStatic<kerf::Fixed> g_ff;

template <class S>
kerf::motion::QueuedSegment<S> g_slots[kN];

template <class S>
struct BandStatic {
  std::uint32_t words[kerf::fit::band_workspace_words(kN)];
  kerf::Vec2<S> scaled[kN];
  kerf::fit::BandVertex<S> vertices[kN];
  kerf::fit::BandWidth<S> widths[kN];
  kerf::fit::Piece<S> pieces[kN];
};
BandStatic<double> g_bd;
BandStatic<kerf::Fixed> g_bf;

template <class S>
struct BiarcStatic {
  std::uint32_t words[kerf::fit::biarc_workspace_words(kN)];
  kerf::fit::BandVertex<S> vertices[kN];
  kerf::Vec2<S> scaled[kN];
  kerf::Vec2<S> tangents[kN];
  kerf::fit::BandWidth<S> widths[kN];
  kerf::fit::BiarcPiece<S> pieces[kN];
};
BiarcStatic<double> g_ad;
BiarcStatic<kerf::Fixed> g_af;

// The biarc fit of the parabola's points at `tol`, tangents estimated.
template <class S>
std::uint32_t biarc_pieces(const FitStatic<S>& pts, BiarcStatic<S>& st, S tol) {
  for (std::size_t k = 0; k < kN; ++k) st.widths[k] = {tol, tol};
  kerf::fit::estimate_tangents<S>({pts.points, kN}, {st.tangents, kN});
  const kerf::fit::BiarcWorkspace<S> ws{st.words, st.vertices, st.scaled};
  const auto r = kerf::fit::fit_biarc_min_count<S>({pts.points, kN}, {st.tangents, kN}, {st.widths, kN}, {},
                                                   ws, st.pieces);
  return r.ok() ? r.value().pieces : 0;
}

// The band fit of the parabola's points at `tol` on both sides.
template <class S>
std::uint32_t band_pieces(const FitStatic<S>& pts, BandStatic<S>& st, S tol) {
  for (std::size_t k = 0; k < kN; ++k) st.widths[k] = {tol, tol};
  const kerf::fit::BandWorkspace<S> ws{st.words, st.scaled, st.vertices};
  const auto r = kerf::fit::fit_band_min_count<S>({pts.points, kN}, {st.widths, kN}, ws, st.pieces);
  return r.ok() ? r.value().pieces : 0;
}

template <class S>
std::uint32_t fit_pieces(FitStatic<S>& st, S tol) {
  const kerf::fit::Workspace<S> ws{st.words, st.intervals, st.scaled};
  const auto r = kerf::fit::fit_min_count<S>({st.points, kN}, tol, kerf::fit::Method::optimal, ws,
                                             st.pieces);
  return r.ok() ? r.value().pieces : 0;
}

// Runs the fitted pieces through the interpolator; the number of periods to
// the end, or 0 when it does not get there.
template <class S>
long interpolate(FitStatic<S>& st, std::uint32_t pieces, S one_ms, S accel, S feed) {
  kerf::motion::Interpolator<S> ip({g_slots<S>, kN});
  kerf::motion::MotionConfig<S> cfg;
  cfg.period = one_ms;
  cfg.accel = accel;
  if (ip.configure(cfg) != kerf::Status::ok) return 0;
  for (std::uint32_t k = 0; k < pieces; ++k)
    if (ip.push({st.pieces[k].segment, feed, k + 1}) != kerf::Status::ok) return 0;
  for (long n = 1; n < 1000000; ++n)
    if (ip.step().state == kerf::motion::MotionState::done) return n;
  return 0;
}

// The streaming fitter, window 32 (forced commits happen) and 256 (none):
// its pieces, or 0 when it fails.
kerf::fit::PointWindow<double, 256> g_window;

std::uint64_t stream_pieces(std::uint32_t window) {
  std::uint64_t pieces = 0;
  auto sink = [&pieces](const kerf::fit::Piece<double>&, bool) { ++pieces; };
  if (g_window.start(0.0183, kerf::fit::Method::optimal, window) != kerf::Status::ok) return 0;
  for (std::size_t k = 0; k < kN; ++k)
    if (g_window.push(g_fd.points[k], sink) != kerf::Status::ok) return 0;
  if (g_window.finish(sink) != kerf::Status::ok) return 0;
  return pieces;
}

kerf::fit::BandWindow<double, 256> g_band_window;

std::uint64_t stream_band_pieces(std::uint32_t window) {
  std::uint64_t pieces = 0;
  auto sink = [&pieces](const kerf::fit::Piece<double>&, bool) { ++pieces; };
  if (g_band_window.start(0.0183, 0.0183, window) != kerf::Status::ok) return 0;
  for (std::size_t k = 0; k < kN; ++k)
    if (g_band_window.push(g_fd.points[k], sink) != kerf::Status::ok) return 0;
  if (g_band_window.finish(sink) != kerf::Status::ok) return 0;
  return pieces;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--self-check") == 0) {
    g_armed = true;
    void* p = std::malloc(16);  // must trap
    g_armed = false;
    std::free(p);
    return 0;
  }
  std::FILE* f = std::fopen(KERF_TEST_DATA_DIR "/curves/parabola.txt", "r");
  if (f == nullptr) return 2;
  for (std::size_t k = 0; k < kN; ++k) {
    double x = 0, y = 0;
    if (std::fscanf(f, "%lf %lf", &x, &y) != 2) return 2;
    g_fd.points[k] = {x, y};
    g_ff.points[k] = {kerf::fixed_from_double(x), kerf::fixed_from_double(y)};
  }
  std::fclose(f);

  g_armed = true;
  const std::uint32_t nd = fit_pieces<double>(g_fd, 0.0183);
  const std::uint32_t nf = fit_pieces<kerf::Fixed>(g_ff, kerf::Fixed(0.0183));
  const std::uint64_t ns_big = stream_pieces(256);
  const std::uint32_t forced_big = g_window.stats().forced;
  const std::uint64_t ns_small = stream_pieces(32);
  const std::uint32_t forced_small = g_window.stats().forced;
  const std::uint64_t nb_big = stream_band_pieces(256);
  const std::uint64_t nb_small = stream_band_pieces(32);
  const std::uint32_t forced_band_small = g_band_window.stats().forced;
  const long td = interpolate<double>(g_fd, nd, 0.001, 1000.0, 100.0);
  const long tf = interpolate<kerf::Fixed>(g_ff, nf, kerf::Fixed(0.001), kerf::Fixed(1000),
                                           kerf::Fixed(100));
  const std::uint32_t bd = band_pieces<double>(g_fd, g_bd, 0.0183);
  const std::uint32_t bf = band_pieces<kerf::Fixed>(g_ff, g_bf, kerf::Fixed(0.0183));
  const std::uint32_t ad = biarc_pieces<double>(g_fd, g_ad, 0.0183);
  const std::uint32_t af = biarc_pieces<kerf::Fixed>(g_ff, g_af, kerf::Fixed(0.0183));
  g_armed = false;

  int failed = 0;
  auto check = [&](bool ok, const char* what) {
    std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
    failed += ok ? 0 : 1;
  };
  check(nd == 5, "double fit of the parabola at 0.0183: 5 pieces");
  check(nf == 5, "fixed fit of the parabola at 0.0183: 5 pieces");
  check(td > 0, "double interpolation reaches the end");
  check(tf > 0 && (tf - td) * (tf - td) <= 4, "fixed interpolation reaches the end within 2 periods of double");
  check(bd == 5, "double band fit of the parabola at 0.0183: 5 pieces");
  check(bf == 5, "fixed band fit of the parabola at 0.0183: 5 pieces");
  check(ad == 4, "double biarc fit of the parabola at 0.0183: 4 biarcs");
  check(af == 4, "fixed biarc fit of the parabola at 0.0183: 4 biarcs");
  check(ns_big == 5 && forced_big == 0, "stream fit, window 256: 5 pieces, no forced commit");
  check(ns_small >= 5 && forced_small > 0, "stream fit, window 32: forced commits, >= 5 pieces");
  check(nb_big == 5, "band stream fit, window 256: 5 pieces (the whole-input count)");
  check(nb_small >= 5 && forced_band_small > 0, "band stream fit, window 32: forced commits, >= 5 pieces");
  std::printf("%d passed, %d failed\n", 10 - failed, failed);
  return failed == 0 ? 0 : 1;
}
