// The band criterion (fit/band.hpp), streamed: BandWindow<S, N> is
// PointWindow's engine (fit/stream.hpp) with the band pair test.
//
// A band gate depends on the edges on both sides of its vertex, and the
// region's convexity narrowing (fit/band/region.hpp) halves a vertex's gate
// when a cell next to it is not convex, which can reach on to the next
// vertex, and so on. The ends of a window's region are path ends (gates
// square to the end edge), where the whole input has ordinary corners. So
// the region is rebuilt over the window each time a point arrives, labels
// trail the newest point by kLag = 3 points and kContext = 3 points are kept
// before the root: pairs are tested and pieces chosen at least three
// vertices away from either end of the window's region. With one point of
// each (the first version) the narrowing at the window's last vertex reached
// a label and changed a piece (a corpus polyline); with 2 or 3, the regions
// agreed with the whole input's wherever the tests looked, and the streamed
// pieces are the whole-input band fitter's at tol itself (tie_break >= 1),
// bit for bit, in double and Fixed (tests/unit/test_stream_exact.cpp). That
// agreement is tested, not proven: a narrowing cascade longer than three
// vertices would break it. Every piece is valid in the region it was chosen
// in, which lies inside the band, and piece() tests it again in the region
// current at commit time (error = infinity if that region refuses it; the CLI
// then fails). The bound (3) of fit/stream.hpp carries over with the optima
// taken in the windows' regions, given that a one-step piece (an edge of the
// polyline) is valid, which the engine assumes.
#pragma once

#include "kerf/fit/band.hpp"
#include "kerf/fit/detail/prefix_guard.hpp"
#include "kerf/fit/stream.hpp"

namespace kerf::fit {

namespace detail {

template <class S, std::size_t N>
struct BandCriterion {
  static constexpr std::uint32_t kLag = 3;
  static constexpr std::uint32_t kContext = 3;

  BandWidth<S> width{};
  S factor = S(1);  // the widths' scale: the points' (StreamEngine::scale_for)
  Slots<BandWidth<S>, N> widths;
  Slots<BandVertex<S>, N> vertices;
  Slots<std::uint32_t, N> next_barrier;  // the first barrier after each vertex
  std::uint32_t filled = 0;              // widths written so far
  BandRegion<S> region;
  S guard_eps{};                         // the longest half gate

  void rescale(S f) { factor = f; }
  void prepare(const Vec2<S>* pts, std::uint32_t n) {
    for (; filled < n; ++filled) widths[filled] = width;
    region = BandRegion<S>(pts, n, vertices.item);
    (void)region.build(widths.item, S(1) * factor);  // always ok: it narrows until convex
    S longest = S(0);
    next_barrier[n - 1] = n;
    for (std::uint32_t k = n; k-- > 0;) {
      if (k + 1 < n) next_barrier[k] = region.vertex(k + 1).barrier ? k + 1 : next_barrier[k + 1];
      longest = max_of(longest, max_of(region.vertex(k).gate_left, region.vertex(k).gate_right));
    }
    guard_eps = longest;
  }
  bool feasible(const Vec2<S>*, std::uint32_t i, std::uint32_t j, std::uint32_t&) {
    return band_pair_valid<S>(region, i, j, nullptr);
  }
  bool alive(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j) {
    if (next_barrier[i] < j) return false;
    return prefix_guard(pts, i, j, guard_eps);
  }
  // error: the largest distance of an inner point from the piece's circle
  // (or line); infinity if the current region refuses the pair (see above).
  Piece<S> piece(const Vec2<S>* pts, std::uint32_t i, std::uint32_t j) {
    Segment<S> seg = Segment<S>::line(pts[i], pts[j]);
    if (!band_pair_valid(region, i, j, &seg)) return Piece<S>{i, j, seg, Scalar<S>::infinity()};
    S error = S(0);
    for (std::uint32_t k = i + 1; k < j; ++k) {
      const S d = seg.is_arc() ? Scalar<S>::abs((pts[k] - seg.centre).norm() - seg.radius())
                               : distance_to_line(seg.start, seg.end, pts[k]);
      error = max_of(error, d);
    }
    return Piece<S>{i, j, seg, error};
  }
};

}  // namespace detail

template <class S, std::size_t N>
class BandWindow : public detail::StreamEngine<S, N, detail::BandCriterion<S, N>> {
 public:
  // Starts a new stream with the band `left` and `right` of the path (each
  // >= 0, one > 0, both finite). invalid_argument otherwise, or for a
  // window outside [kMinWindow = 10, N].
  Status start(S left, S right, std::uint32_t window = static_cast<std::uint32_t>(N)) {
    using M = Scalar<S>;
    if (!M::is_finite(left) || !M::is_finite(right) || left < S(0) || right < S(0) ||
        !(left + right > S(0)))
      return Status::invalid_argument;
    this->crit_.width = BandWidth<S>{left, right};
    this->crit_.factor = S(1);
    this->crit_.filled = 0;
    return this->begin(window);
  }
};

// A compiled instance (src/stream_double.cpp) for the core's symbol scan.
std::uint64_t stream_band_count_window64(BandWindow<double, 64>& w, Span<const Vec2<double>> pts,
                                         double tol);

}  // namespace kerf::fit
