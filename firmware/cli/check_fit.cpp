#include "cli/check_fit.hpp"

#include <cmath>
#include <cstdio>

#include "kerf/geom/segment.hpp"

namespace kerf::cli {

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

}  // namespace kerf::cli
