// Builds the streaming fitter into the core library, so that the core's
// symbol scan (no allocator, throw or stdio) covers it too. PointWindow is a
// header template; this one instance is what the scan sees.
#include "kerf/fit/stream.hpp"
#include "kerf/fit/stream_band.hpp"

namespace kerf::fit {

namespace {

struct CountingSink {
  std::uint64_t pieces = 0;
  void operator()(const Piece<double>&, bool) { ++pieces; }
};

}  // namespace

// Pieces of a stream fit of pts through a window of 64, or 0 on an error.
std::uint64_t stream_count_window64(PointWindow<double, 64>& w, Span<const Vec2<double>> pts,
                                    double tol) {
  CountingSink sink;
  if (w.start(tol, Method::optimal) != Status::ok) return 0;
  for (const Vec2<double>& p : pts)
    if (w.push(p, sink) != Status::ok) return 0;
  return w.finish(sink) == Status::ok ? sink.pieces : 0;
}

std::uint64_t stream_band_count_window64(BandWindow<double, 64>& w, Span<const Vec2<double>> pts,
                                         double tol) {
  CountingSink sink;
  if (w.start(tol, tol) != Status::ok) return 0;
  for (const Vec2<double>& p : pts)
    if (w.push(p, sink) != Status::ok) return 0;
  return w.finish(sink) == Status::ok ? sink.pieces : 0;
}

}  // namespace kerf::fit
