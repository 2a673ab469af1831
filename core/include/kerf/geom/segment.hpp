// A piece of a cut path: a circular arc {start, end, centre, E} or a line,
// which is the arc's infinite-radius limit. E = +1 runs counter-clockwise
// around the centre, E = -1 clockwise (the ESGI'104 output convention).
#pragma once

#include <cstdint>

#include "kerf/geom/vec2.hpp"

namespace kerf {

enum class SegmentKind : std::uint8_t { line, arc };

template <class S>
struct Segment {
  SegmentKind kind = SegmentKind::line;
  Vec2<S> start{};
  Vec2<S> end{};
  Vec2<S> centre{};      // meaningful for arcs only
  std::int8_t dir = 0;   // E: +1 CCW, -1 CW; 0 for lines

  static constexpr Segment line(Vec2<S> a, Vec2<S> b) { return {SegmentKind::line, a, b, {}, 0}; }
  static constexpr Segment arc(Vec2<S> a, Vec2<S> b, Vec2<S> c, int e) {
    return {SegmentKind::arc, a, b, c, static_cast<std::int8_t>(e > 0 ? 1 : -1)};
  }
  constexpr bool is_arc() const { return kind == SegmentKind::arc; }
  S radius() const { return (start - centre).norm(); }
};

// Distance from p to the infinite line through a and b (a != b).
template <class S>
S distance_to_line(Vec2<S> a, Vec2<S> b, Vec2<S> p) {
  const Vec2<S> d = b - a;
  return Scalar<S>::abs(d.cross(p - a)) / d.norm();
}

// Distance from p to the closed line segment ab.
template <class S>
S distance_to_line_segment(Vec2<S> a, Vec2<S> b, Vec2<S> p) {
  const Vec2<S> d = b - a;
  const S len2 = d.norm2();
  if (len2 == S(0)) return distance(a, p);
  const S t = d.dot(p - a);
  if (t <= S(0)) return distance(a, p);
  if (t >= len2) return distance(b, p);
  return Scalar<S>::abs(d.cross(p - a)) / Scalar<S>::sqrt(len2);
}

// Distance from p to the full circle around `centre` through `on` (the ESGI
// error of a point). Written as (|p-c|^2 - |on-c|^2) / (|p-c| + |on-c|) with
// the numerator as (p - on).(p + on - 2c), so that it does not cancel when the
// radius is huge, as it does for nearly straight arcs.
template <class S>
S distance_to_circle(Vec2<S> centre, Vec2<S> on, Vec2<S> p) {
  const S power = (p - on).dot(p + on - centre * S(2));
  const S sum = (p - centre).norm() + (on - centre).norm();
  return sum > S(0) ? Scalar<S>::abs(power) / sum : S(0);
}

// True when direction v (from the centre) lies within the sweep that starts at
// direction a and turns by E towards direction b. Ends are included.
template <class S>
bool in_sweep(Vec2<S> a, Vec2<S> b, Vec2<S> v, int e) {
  if (e < 0) {  // a clockwise sweep from a to b is the CCW sweep from b to a
    Vec2<S> t = a;
    a = b;
    b = t;
  }
  const S ab = a.cross(b);
  const S av = a.cross(v);
  const S vb = v.cross(b);
  if (ab > S(0) || (ab == S(0) && a.dot(b) > S(0))) return av >= S(0) && vb >= S(0);
  return !(av < S(0) && vb < S(0));  // sweep of pi or more: all but the opposite wedge
}

// Distance from p to the segment as drawn: for an arc, the nearest point of
// the swept arc; for a line, of the line segment.
template <class S>
S distance_to_segment(const Segment<S>& s, Vec2<S> p) {
  if (!s.is_arc()) return distance_to_line_segment(s.start, s.end, p);
  const Vec2<S> v = p - s.centre;
  if (v.norm2() != S(0) && in_sweep(s.start - s.centre, s.end - s.centre, v, s.dir))
    return distance_to_circle(s.centre, s.start, p);
  const S da = distance(s.start, p);
  const S db = distance(s.end, p);
  return da < db ? da : db;
}

}  // namespace kerf
