#include "job/check_fit.hpp"

#include <cmath>
#include <cstdio>

#include "kerf/geom/segment.hpp"

namespace kerf::job {

namespace {

double extent(Span<const Vec2<double>> pts) {
  double lo_x = pts[0].x, hi_x = pts[0].x, lo_y = pts[0].y, hi_y = pts[0].y;
  for (const Vec2<double>& p : pts) {
    lo_x = std::fmin(lo_x, p.x);
    hi_x = std::fmax(hi_x, p.x);
    lo_y = std::fmin(lo_y, p.y);
    hi_y = std::fmax(hi_y, p.y);
  }
  return std::hypot(hi_x - lo_x, hi_y - lo_y);
}

std::string piece_error(std::size_t k, const std::string& what) {
  std::string s = "piece ";
  s += std::to_string(k + 1);
  s += ": ";
  s += what;
  return s;
}

constexpr double kTwoPi = 6.283185307179586;

// [0, 2 pi)
double wrap(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0.0 ? a + kTwoPi : a;
}

// Does the arc follow its points in order? Walking the points from start to
// end, each step turns about the centre (in the arc's direction; a step back
// of up to 90 degrees counts as backwards) and the total must be the arc's
// sweep, never running past it or back before the start by more than the tol
// allows. A point path that winds round more than once, or the other way,
// cannot be one arc even when every point is near its circle. Skipped for
// radii within the tol, where any order is within tol of the arc.
bool follows_in_order(Span<const Vec2<double>> pts, const fit::Piece<double>& pc, double tol) {
  const Segment<double>& s = pc.segment;
  const double r = s.radius();
  if (!(r > tol)) return true;
  const double slack = 2.0 * tol / r;
  auto angle = [&](Vec2<double> p) { return std::atan2(p.y - s.centre.y, p.x - s.centre.x); };
  const double sweep = s.start == s.end ? kTwoPi : wrap(s.dir * (angle(s.end) - angle(s.start)));
  double walked = 0.0, prev = angle(s.start);
  for (std::uint32_t i = pc.first + 1; i <= pc.last; ++i) {
    const double a = angle(pts[i]);
    double step = wrap(s.dir * (a - prev));
    if (step > 1.5 * 3.141592653589793) step -= kTwoPi;  // a small step backwards
    walked += step;
    prev = a;
    if (walked < -slack || walked > sweep + slack) return false;
  }
  return std::fabs(walked - sweep) <= slack;
}

}  // namespace

std::string check_fit(Span<const Vec2<double>> pts, Span<const fit::Piece<double>> pieces,
                      double tol) {
  const std::size_t n = pts.size();
  if (pieces.empty()) return "no pieces";
  if (pieces[0].first != 0) return piece_error(0, "does not start at the first point");
  if (pieces[pieces.size() - 1].last != n - 1)
    return piece_error(pieces.size() - 1, "does not end at the last point");
  const double limit = tol * (1.0 + 1e-6) + extent(pts) * 1e-12;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const fit::Piece<double>& pc = pieces[k];
    const Segment<double>& s = pc.segment;
    if (k > 0 && pc.first != pieces[k - 1].last) return piece_error(k, "does not follow on");
    if (pc.first >= pc.last || pc.last >= n) return piece_error(k, "bad point indices");
    if (!(s.start == pts[pc.first]) || !(s.end == pts[pc.last]))
      return piece_error(k, "does not run between its points");
    if (s.is_arc() && (s.dir != 1 && s.dir != -1)) return piece_error(k, "arc without direction");
    const double radius = s.is_arc() ? s.radius() : 0.0;
    if (s.is_arc() && !(std::isfinite(radius) && radius > 0.0))
      return piece_error(k, "arc without a finite radius");
    if (s.is_arc() && !follows_in_order(pts, pc, tol))
      return piece_error(k, "the arc does not pass its points in order (they wind round "
                            "more than once, or the other way)");
    for (std::uint32_t i = pc.first + 1; i < pc.last; ++i) {
      const double d = s.is_arc() ? distance_to_circle(s.centre, s.start, pts[i])
                                  : distance_to_line(s.start, s.end, pts[i]);
      if (!(d <= limit)) {
        char buf[96];
        std::snprintf(buf, sizeof buf, " is %.6g from it, more than tol %.6g", d, tol);
        return piece_error(k, "point " + std::to_string(i + 1) + buf);
      }
    }
  }
  return {};
}

}  // namespace kerf::job
