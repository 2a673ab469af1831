// The one contract between the fit and the board: which segments a board
// runs (segment_flaw, used by prepare_segment when a segment is queued) and
// how a fitted piece becomes such a segment on the link's grid (emit_on_grid,
// used by the host when it turns a fit into a job).
//
// Why a grid: a link carries coordinates as integer counts (Modbus: 1 um,
// hal/modbus/REGISTERS.md), and the board starts each segment where the
// previous one ended. A fitted piece shorter than a count, or an arc whose
// ends move by half a count, can become a zero-length line or an arc whose
// sweep is 0 or 2 pi on the board, although it was fine on the host.
// emit_on_grid rounds on the host, checks what the board will check, and
// gives the board exactly that geometry: rounding a grid point again is
// exact, so the board sees what the host checked.
#pragma once

#include <cstdint>

#include "kerf/core/fixed.hpp"
#include "kerf/core/scalar.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf::motion {

// Why a segment is refused; none when it runs.
enum class SegmentFlaw : std::uint8_t {
  none,
  not_finite,     // a coordinate is inf or NaN (or a saturated Fixed)
  zero_length,    // a line whose ends coincide
  zero_radius,    // an arc whose start or end is its centre
  sweep_range,    // an arc whose sweep is not in (0, 2 pi): its ends coincide
};

// What the board works out from an acceptable segment.
template <class S>
struct SegmentShape {
  S length{};  // mm along the path
  S radius{};  // arcs: |start - centre|
  S sweep{};   // arcs: in the direction of travel, in (0, 2 pi)
};

// The board's acceptance of a segment's geometry. Fills `shape` when none.
template <class S>
SegmentFlaw segment_flaw(const Segment<S>& g, SegmentShape<S>& shape) {
  using Sc = Scalar<S>;
  const bool finite = Sc::is_finite(g.start.x) && Sc::is_finite(g.start.y) && Sc::is_finite(g.end.x) &&
                      Sc::is_finite(g.end.y) && Sc::is_finite(g.centre.x) && Sc::is_finite(g.centre.y);
  if (!finite) return SegmentFlaw::not_finite;
  if (!g.is_arc()) {
    shape.length = (g.end - g.start).norm();
    shape.radius = S(0);
    shape.sweep = S(0);
    return shape.length > S(0) ? SegmentFlaw::none : SegmentFlaw::zero_length;
  }
  const Vec2<S> a = g.start - g.centre;
  const Vec2<S> b = g.end - g.centre;
  const S r = a.norm();
  if (!(r > S(0)) || !(b.norm() > S(0))) return SegmentFlaw::zero_radius;
  const S e = g.dir > 0 ? S(1) : S(-1);
  S sweep = Sc::atan2(a.cross(b), a.dot(b)) * e;
  if (!(sweep > S(0))) sweep = sweep + S(2) * Sc::pi();
  if (!(sweep > S(0)) || !(sweep < S(2) * Sc::pi())) return SegmentFlaw::sweep_range;
  shape.radius = r;
  shape.sweep = sweep;
  shape.length = r * sweep;
  return SegmentFlaw::none;
}

template <class S>
bool segment_acceptable(const Segment<S>& g) {
  SegmentShape<S> shape;
  return segment_flaw(g, shape) == SegmentFlaw::none;
}

// The link's grid: per_mm counts per mm (1000 for 1 um), coordinates up to
// max_counts in magnitude (a 32-bit register: 2^31 - 1).
struct SegmentGrid {
  std::int32_t per_mm = 1000;
  std::int64_t max_counts = 2147483647;
};

namespace contract_detail {
// Nearest integer, ties away from zero; false beyond +-2^62 (or not finite).
inline bool nearest_count(double v, std::int64_t& out) {
  if (!(v > -4.6e18 && v < 4.6e18)) return false;
  out = v < 0 ? -static_cast<std::int64_t>(-v + 0.5) : static_cast<std::int64_t>(v + 0.5);
  return true;
}
inline bool nearest_count(Fixed v, std::int64_t& out) {
  if (!Scalar<Fixed>::is_finite(v)) return false;
  const std::int64_t half = std::int64_t{1} << (Fixed::frac_bits - 1);
  const std::int64_t r = v.raw();
  out = r < 0 ? -((-r + half) >> Fixed::frac_bits) : (r + half) >> Fixed::frac_bits;
  return true;
}
}  // namespace contract_detail

// p rounded to the nearest grid point; false when it lies beyond the grid.
template <class S>
bool snap_to_grid(Vec2<S> p, const SegmentGrid& grid, Vec2<S>& out) {
  const S n = S(grid.per_mm);
  std::int64_t kx = 0, ky = 0;
  if (!contract_detail::nearest_count(p.x * n, kx) || !contract_detail::nearest_count(p.y * n, ky)) return false;
  if (kx > grid.max_counts || kx < -grid.max_counts || ky > grid.max_counts || ky < -grid.max_counts)
    return false;
  out = {S(kx) / n, S(ky) / n};
  return true;
}

// At most this many segments per fitted piece (an arc split in two halves).
inline constexpr int kMaxEmitted = 2;

enum class EmitStatus : std::uint8_t {
  ok,
  off_grid,  // an end point lies beyond the link's range
  refused,   // the fitted piece itself is not a segment (see segment_flaw)
};

template <class S>
struct Emitted {
  EmitStatus status = EmitStatus::ok;
  int count = 0;  // 0: the piece is shorter than the grid and merges into the next
  Segment<S> segments[kMaxEmitted]{};
  int lines_for_arcs = 0;  // arcs given as their chord (see emit_on_grid)
};

// The largest sweep change that rounding may cause in an arc that keeps its
// shape. A wrap through 0 or 2 pi changes it by nearly 2 pi.
template <class S>
constexpr S kSweepSlack = S(0.5);

namespace contract_detail {

// The arc from `from` to the grid point nearest `fitted.end`, about the grid
// point nearest its centre, when the board accepts it and its sweep is the
// fitted one's (within kSweepSlack). Otherwise false.
template <class S>
bool arc_on_grid(Vec2<S> from, const Segment<S>& fitted, S fitted_sweep, const SegmentGrid& grid,
                 Vec2<S> end, Segment<S>& out) {
  Vec2<S> c{};
  if (!snap_to_grid(fitted.centre, grid, c)) return false;  // a flat arc past the range: its chord
  const Segment<S> g = Segment<S>::arc(from, end, c, fitted.dir);
  SegmentShape<S> shape;
  if (segment_flaw(g, shape) != SegmentFlaw::none) return false;
  if (Scalar<S>::abs(shape.sweep - fitted_sweep) > kSweepSlack<S>) return false;
  out = g;
  return true;
}

}  // namespace contract_detail

// The segments the board runs for one fitted piece, starting at `from` (a
// grid point: the previous segment's emitted end, or the path's snapped
// start). Every segment returned passes segment_flaw as it is and after the
// link's rounding (its points are grid points). Deviation from the fitted
// piece, with q = 1 / per_mm:
//   - ends and centre move by at most q/sqrt(2) each (the rounding itself);
//   - a piece whose end rounds onto `from` emits nothing: it spans at most
//     about 1.5 q, and the next piece starts there (merged);
//   - an arc that does not survive rounding (its sweep would wrap through 0
//     or 2 pi, or its centre lies beyond the grid) is split at its middle
//     when its sweep exceeds pi/2, and otherwise, or when a half still does
//     not survive, given as its chord. That happens only to arcs whose
//     radius is a few q (the chord of a sweep up to pi/2 lies within 0.3 r
//     of the arc; the unit tests measure under 3 q in all) or whose
//     centre is beyond the grid's range (over 2 km for 1 um counts: their
//     sagitta on any cut is below q).
template <class S>
Emitted<S> emit_on_grid(Vec2<S> from, const Segment<S>& fitted, const SegmentGrid& grid) {
  Emitted<S> out;
  SegmentShape<S> fitted_shape;
  if (segment_flaw(fitted, fitted_shape) != SegmentFlaw::none) {
    out.status = EmitStatus::refused;
    return out;
  }
  Vec2<S> end{};
  if (!snap_to_grid(fitted.end, grid, end)) {
    out.status = EmitStatus::off_grid;
    return out;
  }
  if (fitted.is_arc()) {
    if (contract_detail::arc_on_grid(from, fitted, fitted_shape.sweep, grid, end, out.segments[0])) {
      out.count = 1;
      return out;
    }
    if (fitted_shape.sweep > Scalar<S>::pi() / S(2)) {
      // Split at the middle of the fitted arc, on its circle.
      const Vec2<S> a = fitted.start - fitted.centre;
      const S half = fitted_shape.sweep / S(2) * (fitted.dir > 0 ? S(1) : S(-1));
      const S c = Scalar<S>::cos(half), s = Scalar<S>::sin(half);
      const Vec2<S> mid_exact = fitted.centre + Vec2<S>{a.x * c - a.y * s, a.x * s + a.y * c};
      Vec2<S> mid{};
      if (!snap_to_grid(mid_exact, grid, mid)) {
        out.status = EmitStatus::off_grid;
        return out;
      }
      const Segment<S> first = Segment<S>::arc(fitted.start, mid_exact, fitted.centre, fitted.dir);
      const Segment<S> second = Segment<S>::arc(mid_exact, fitted.end, fitted.centre, fitted.dir);
      const S half_sweep = fitted_shape.sweep / S(2);
      Segment<S> h{};
      if (!(mid == from)) {
        const bool arc = contract_detail::arc_on_grid(from, first, half_sweep, grid, mid, h);
        out.segments[out.count++] = arc ? h : Segment<S>::line(from, mid);
        out.lines_for_arcs += arc ? 0 : 1;
      }
      if (!(mid == end)) {
        const Vec2<S> at = out.count > 0 ? mid : from;
        const bool arc = contract_detail::arc_on_grid(at, second, half_sweep, grid, end, h);
        if (arc || !(at == end)) {
          out.segments[out.count++] = arc ? h : Segment<S>::line(at, end);
          out.lines_for_arcs += arc ? 0 : 1;
        }
      }
      return out;
    }
    out.lines_for_arcs = end == from ? 0 : 1;
  }
  if (end == from) return out;  // shorter than the grid: merged into the next piece
  out.segments[out.count++] = Segment<S>::line(from, end);
  return out;
}

}  // namespace kerf::motion
