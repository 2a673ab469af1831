// Arc-length geometry of one segment, worked out once when it is queued:
// length, tangents, and the point at a distance u from its start. Points on
// an arc come from the centre and the angle start_angle + E u / r every time,
// never from accumulated small rotations.
#pragma once

#include "kerf/core/status.hpp"
#include "kerf/motion/path_queue.hpp"

namespace kerf::motion {

// Fills the derived fields of a queued segment. invalid_argument for a feed
// that is not a finite number > 0, a non-finite coordinate, or a segment of
// zero length (a line whose ends coincide, an arc of zero radius or sweep).
template <class S>
Result<QueuedSegment<S>> prepare_segment(const PathSegment<S>& p) {
  using Sc = Scalar<S>;
  const Segment<S>& g = p.geometry;
  const bool finite = Sc::is_finite(p.feed) && Sc::is_finite(g.start.x) &&
                      Sc::is_finite(g.start.y) && Sc::is_finite(g.end.x) &&
                      Sc::is_finite(g.end.y) && Sc::is_finite(g.centre.x) &&
                      Sc::is_finite(g.centre.y);
  if (!finite || !(p.feed > S(0))) return Status::invalid_argument;
  QueuedSegment<S> q;
  q.path = p;
  if (!g.is_arc()) {
    const Vec2<S> d = g.end - g.start;
    q.length = d.norm();
    if (!(q.length > S(0))) return Status::invalid_argument;
    q.tangent_in = d * (S(1) / q.length);
    q.tangent_out = q.tangent_in;
    return q;
  }
  const Vec2<S> a = g.start - g.centre;
  const Vec2<S> b = g.end - g.centre;
  q.radius = a.norm();
  if (!(q.radius > S(0)) || !(b.norm() > S(0))) return Status::invalid_argument;
  const S e = g.dir > 0 ? S(1) : S(-1);
  // sweep in the direction of travel, in (0, 2 pi)
  S sweep = Sc::atan2(a.cross(b), a.dot(b)) * e;
  if (!(sweep > S(0))) sweep = sweep + S(2) * Sc::pi();
  if (!(sweep > S(0)) || !(sweep < S(2) * Sc::pi())) return Status::invalid_argument;
  q.length = q.radius * sweep;
  q.start_angle = Sc::atan2(a.y, a.x);
  q.tangent_in = a.perp() * (e / q.radius);
  q.tangent_out = b.perp() * (e / b.norm());
  return q;
}

// The point at distance u (0 <= u <= length) from the segment's start. The
// end itself is returned exactly, so consecutive segments meet without a seam.
template <class S>
Vec2<S> point_at(const QueuedSegment<S>& q, S u) {
  const Segment<S>& g = q.path.geometry;
  if (!(u < q.length)) return g.end;
  if (!g.is_arc()) return g.start + q.tangent_in * u;
  const S phi = q.start_angle + (g.dir > 0 ? u : -u) / q.radius;
  return g.centre + Vec2<S>{Scalar<S>::cos(phi), Scalar<S>::sin(phi)} * q.radius;
}

}  // namespace kerf::motion
