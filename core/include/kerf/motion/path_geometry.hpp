// Arc-length geometry of one segment, worked out once when it is queued:
// length, tangents, and the point at a distance u from its start. Points on
// an arc come from the centre and the angle start_angle + E u / r every time,
// never from accumulated small rotations.
//
// An arc whose end is not exactly on its circle (coordinates rounded to the
// link's grid put it up to a count off; G-code allows a small difference, as
// LinuxCNC does) is run as a spiral: the radius goes linearly from the start's
// to the end's, so the axes reach the end without a step in the last period.
#pragma once

#include "kerf/core/status.hpp"
#include "kerf/motion/path_queue.hpp"
#include "kerf/motion/segment_contract.hpp"

namespace kerf::motion {

// Fills the derived fields of a queued segment. invalid_argument for a feed
// that is not a finite number > 0, or a geometry the board refuses
// (segment_contract.hpp: segment_flaw, the contract with the fit).
template <class S>
Result<QueuedSegment<S>> prepare_segment(const PathSegment<S>& p) {
  const Segment<S>& g = p.geometry;
  if (!Scalar<S>::is_finite(p.feed) || !(p.feed > S(0))) return Status::invalid_argument;
  SegmentShape<S> shape;
  if (segment_flaw(g, shape) != SegmentFlaw::none) return Status::invalid_argument;
  QueuedSegment<S> q;
  q.path = p;
  q.length = shape.length;
  if (!g.is_arc()) {
    q.tangent_in = (g.end - g.start) * (S(1) / q.length);
    q.tangent_out = q.tangent_in;
    return q;
  }
  const Vec2<S> a = g.start - g.centre;
  const Vec2<S> b = g.end - g.centre;
  const S e = g.dir > 0 ? S(1) : S(-1);
  q.radius = shape.radius;
  q.radius_change = b.norm() - q.radius;
  q.start_angle = Scalar<S>::atan2(a.y, a.x);
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
  const S r = q.radius_change == S(0) ? q.radius : q.radius + q.radius_change * (u / q.length);
  return g.centre + Vec2<S>{Scalar<S>::cos(phi), Scalar<S>::sin(phi)} * r;
}

}  // namespace kerf::motion
