// Soft limits: the box of machine coordinates the axes may reach (LinuxCNC's
// [AXIS_n] MIN_LIMIT / MAX_LIMIT), and the extent a segment sweeps, arcs'
// bulges included. The host checks a whole job against it before the torch
// fires (firmware/control/soft_limits.hpp); a board's executor checks each
// segment again before it moves (BoardExecutor::set_soft_limits), as a second
// line of defence. Freestanding, for double and Fixed.
#pragma once

#include <cstdint>

#include "kerf/motion/board_protocol.hpp"

namespace kerf::motion {

// The fault bit the executor raises for a segment outside the soft limits.
inline constexpr std::uint16_t kBoardFaultSoftLimit = 1u << 9;

// The box a segment sweeps: its ends, and for an arc each axis extreme of its
// circle that lies on the arc.
template <class S>
struct Extent {
  Vec2<S> lo{}, hi{};
};

template <class S>
struct SoftLimits {
  bool on[2] = {false, false};  // per axis (x, y); off: unlimited
  S min[2]{}, max[2]{};         // mm, machine coordinates, min < max

  bool contains(Vec2<S> p) const { return inside(p.x, 0) && inside(p.y, 1); }
  bool contains(const Extent<S>& e) const { return contains(e.lo) && contains(e.hi); }
  bool inside(S v, int axis) const { return !on[axis] || (min[axis] <= v && v <= max[axis]); }
};

namespace soft_limits_detail {

// Whether the direction d (from the centre) lies on the counter-clockwise arc
// from u to v (u == v: the full circle).
template <class S>
bool on_ccw_arc(Vec2<S> u, Vec2<S> v, Vec2<S> d) {
  const S zero{};
  const S uv = u.cross(v);
  if (uv > zero) return u.cross(d) >= zero && d.cross(v) >= zero;
  if (uv < zero) return !(v.cross(d) > zero && d.cross(u) > zero);
  if (u.dot(v) > zero) return true;  // the ends coincide: a full circle
  return u.cross(d) >= zero;         // a half circle, counter-clockwise from u
}

}  // namespace soft_limits_detail

template <class S>
Extent<S> segment_extent(Vec2<S> from, SegmentKind kind, Vec2<S> end, Vec2<S> centre, int dir) {
  Extent<S> e{{min_of(from.x, end.x), min_of(from.y, end.y)}, {max_of(from.x, end.x), max_of(from.y, end.y)}};
  if (kind != SegmentKind::arc) return e;
  Vec2<S> u = from - centre, v = end - centre;
  if (dir < 0) {  // clockwise from u to v is counter-clockwise from v to u
    const Vec2<S> t = u;
    u = v;
    v = t;
  }
  const S r = (from - centre).norm();
  const S one = S(1), zero{};
  if (soft_limits_detail::on_ccw_arc(u, v, Vec2<S>{one, zero})) e.hi.x = max_of(e.hi.x, centre.x + r);
  if (soft_limits_detail::on_ccw_arc(u, v, Vec2<S>{-one, zero})) e.lo.x = min_of(e.lo.x, centre.x - r);
  if (soft_limits_detail::on_ccw_arc(u, v, Vec2<S>{zero, one})) e.hi.y = max_of(e.hi.y, centre.y + r);
  if (soft_limits_detail::on_ccw_arc(u, v, Vec2<S>{zero, -one})) e.lo.y = min_of(e.lo.y, centre.y - r);
  return e;
}

template <class S>
Extent<S> segment_extent(Vec2<S> from, const BoardSegment<S>& seg) {
  return segment_extent(from, seg.kind, seg.end, seg.centre, seg.dir);
}

}  // namespace kerf::motion
