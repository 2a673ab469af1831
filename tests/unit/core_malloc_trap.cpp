// The core never allocates, proven at run time: this program replaces malloc,
// calloc, realloc and operator new with a trap that aborts while armed, then
// runs the vertex fitter, the band fitter and the interpolator in double and
// in kerf::Fixed on the report's parabola, all storage static. `--self-check` allocates while
// armed and must die with the trap's message, which shows the trap is live.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>

#include "kerf/core/fixed_convert.hpp"
#include "kerf/fit/band_fit.hpp"
#include "kerf/fit/fit.hpp"
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
  const long td = interpolate<double>(g_fd, nd, 0.001, 1000.0, 100.0);
  const long tf = interpolate<kerf::Fixed>(g_ff, nf, kerf::Fixed(0.001), kerf::Fixed(1000),
                                           kerf::Fixed(100));
  const std::uint32_t bd = band_pieces<double>(g_fd, g_bd, 0.0183);
  const std::uint32_t bf = band_pieces<kerf::Fixed>(g_ff, g_bf, kerf::Fixed(0.0183));
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
  std::printf("%d passed, %d failed\n", 6 - failed, failed);
  return failed == 0 ? 0 : 1;
}
