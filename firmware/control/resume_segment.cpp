#include "control/resume_segment.hpp"

#include <cmath>

#include "control/fit_paths.hpp"
#include "kerf/motion/segment_contract.hpp"

namespace kerf::control {

namespace {

constexpr double kTwoPi = 6.283185307179586;

// How far along `g` (from its start) the point p lies: mm for a line, the
// angle in the direction of travel in [0, 2 pi) for an arc.
double along(const Segment<double>& g, Vec2<double> p) {
  if (!g.is_arc()) {
    const Vec2<double> d = g.end - g.start;
    return d.dot(p - g.start) / d.norm();
  }
  const Vec2<double> a = g.start - g.centre, b = p - g.centre;
  double phi = std::atan2(a.cross(b), a.dot(b)) * (g.dir > 0 ? 1.0 : -1.0);
  if (phi < 0) phi += kTwoPi;
  return phi;
}

}  // namespace

ResumedSegment resume_segment(const hal::SegmentCommand& seg, Vec2<double> start, Vec2<double> at) {
  ResumedSegment r;
  const Segment<double> g = seg.kind == SegmentKind::arc ? Segment<double>::arc(start, seg.end, seg.centre, seg.dir)
                                                         : Segment<double>::line(start, seg.end);
  motion::SegmentShape<double> shape;
  Vec2<double> p{};
  const bool ok = motion::segment_flaw(g, shape) == motion::SegmentFlaw::none && motion::snap_to_grid(at, kLinkGrid, p);
  if (ok) {
    // Past the end (an arc: nearer its end than its start, going round) or on it: cut whole.
    const double s = along(g, p);
    const double end = g.is_arc() ? shape.sweep : shape.length;
    const double gap = g.is_arc() ? (kTwoPi - shape.sweep) / 2 : kTwoPi;  // lines have no wrap
    if (p == seg.end || (s >= end && s - end < gap)) {
      r.whole = true;
      r.from = seg.end;
      return r;
    }
    const Segment<double> rest = g.is_arc() ? Segment<double>::arc(p, seg.end, seg.centre, seg.dir)
                                            : Segment<double>::line(p, seg.end);
    const motion::Emitted<double> em = motion::emit_on_grid(p, rest, kLinkGrid);
    if (em.status == motion::EmitStatus::ok && em.count == 0) {  // shorter than a count: cut whole
      r.whole = true;
      r.from = seg.end;
      return r;
    }
    if (em.status == motion::EmitStatus::ok) {
      r.from = p;
      r.count = em.count;
      for (int k = 0; k < em.count; ++k) {
        hal::SegmentCommand c = seg;
        c.kind = em.segments[k].kind;
        c.end = em.segments[k].end;
        c.centre = em.segments[k].centre;
        c.dir = em.segments[k].dir;
        r.segments[k] = c;
      }
      return r;
    }
  }
  r.from = start;
  r.count = 1;
  r.segments[0] = seg;
  return r;
}

}  // namespace kerf::control
