#include "verifier.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace kerf_test {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRel = 1e-9;

double wrap_2pi(double a) {
  a = std::fmod(a, 2 * kPi);
  if (a < 0) a += 2 * kPi;
  return a;
}

// |p - c| - r for the circle around c through s, as
// (|p-c|^2 - |s-c|^2) / (|p-c| + |s-c|) = ((p-s).(p-c + s-c)) / (|p-c| + |s-c|),
// which keeps its relative accuracy for huge radii.
double circle_offset(double px, double py, double sx, double sy, double cx, double cy) {
  const double ux = px - cx, uy = py - cy;
  const double wx = sx - cx, wy = sy - cy;
  const double num = (px - sx) * (ux + wx) + (py - sy) * (uy + wy);
  const double den = std::hypot(ux, uy) + std::hypot(wx, wy);
  return den > 0 ? num / den : 0.0;
}

// Signed distance of p from the line through s and e (> 0 on the left of s->e).
double line_offset(double px, double py, double sx, double sy, double ex, double ey) {
  const double dx = ex - sx, dy = ey - sy;
  const double len = std::hypot(dx, dy);
  return (dx * (py - sy) - dy * (px - sx)) / len;
}

bool finite(const VPiece& p) {
  return std::isfinite(p.sx) && std::isfinite(p.sy) && std::isfinite(p.ex) && std::isfinite(p.ey) &&
         (!p.arc || (std::isfinite(p.cx) && std::isfinite(p.cy)));
}

bool near(double a, double b, double scale) { return std::abs(a - b) <= kRel * scale; }

}  // namespace

double scale_of(const std::vector<VPoint>& pts) {
  if (pts.empty()) return 1.0;
  double lox = pts[0].x, hix = pts[0].x, loy = pts[0].y, hiy = pts[0].y;
  for (const VPoint& p : pts) {
    lox = std::min(lox, p.x);
    hix = std::max(hix, p.x);
    loy = std::min(loy, p.y);
    hiy = std::max(hiy, p.y);
  }
  const double d = std::hypot(hix - lox, hiy - loy);
  return d > 0 ? d : 1.0;
}

double arc_distance(const VPoint& p, const VPiece& pc) {
  const double to_start = std::hypot(p.x - pc.sx, p.y - pc.sy);
  const double to_end = std::hypot(p.x - pc.ex, p.y - pc.ey);
  const double ends = std::min(to_start, to_end);
  if (!pc.arc) {
    const double dx = pc.ex - pc.sx, dy = pc.ey - pc.sy;
    const double t = ((p.x - pc.sx) * dx + (p.y - pc.sy) * dy) / (dx * dx + dy * dy);
    if (t < 0 || t > 1) return ends;
    return std::abs(line_offset(p.x, p.y, pc.sx, pc.sy, pc.ex, pc.ey));
  }
  const double a0 = std::atan2(pc.sy - pc.cy, pc.sx - pc.cx);
  const double a1 = std::atan2(pc.ey - pc.cy, pc.ex - pc.cx);
  const double ap = std::atan2(p.y - pc.cy, p.x - pc.cx);
  const double sweep = pc.dir > 0 ? wrap_2pi(a1 - a0) : wrap_2pi(a0 - a1);
  const double pos = pc.dir > 0 ? wrap_2pi(ap - a0) : wrap_2pi(a0 - ap);
  const double circle = std::abs(circle_offset(p.x, p.y, pc.sx, pc.sy, pc.cx, pc.cy));
  return pos <= sweep ? circle : std::max(circle, ends);
}

double piece_error(const std::vector<VPoint>& pts, const VPiece& pc) {
  double worst = 0;
  for (std::size_t k = pc.first + 1; k < pc.last && k < pts.size(); ++k)
    worst = std::max(worst, arc_distance(pts[k], pc));
  return worst;
}

VerifyReport verify(const std::vector<VPoint>& pts, const std::vector<VPiece>& pieces, double tol,
                    Reach reach) {
  std::ostringstream why;
  why.precision(17);
  auto fail = [&](std::size_t k) -> std::ostringstream& {
    why << "piece " << k << ": ";
    return why;
  };
  auto report = [&]() { return VerifyReport{false, why.str()}; };

  const std::size_t n = pts.size();
  if (n < 2) {
    why << "fewer than two points";
    return report();
  }
  if (!(tol > 0) || !std::isfinite(tol)) {
    why << "tolerance " << tol << " is not positive and finite";
    return report();
  }
  if (pieces.empty()) {
    why << "no pieces";
    return report();
  }
  const double scale = scale_of(pts);
  const double lim = tol * (1 + kRel) + 1e-12 * scale;

  std::size_t at = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const VPiece& pc = pieces[k];
    if (pc.first != at) {
      fail(k) << "starts at index " << pc.first << ", expected " << at << " (not contiguous)";
      return report();
    }
    if (!(pc.first < pc.last) || pc.last >= n) {
      fail(k) << "bad index range " << pc.first << " -> " << pc.last << " for " << n << " points";
      return report();
    }
    at = pc.last;
    if (!finite(pc)) {
      fail(k) << "non-finite coordinates";
      return report();
    }
    const VPoint& a = pts[pc.first];
    const VPoint& b = pts[pc.last];
    const double sa = std::max(scale, std::max(std::abs(a.x), std::abs(a.y)));
    const double sb = std::max(scale, std::max(std::abs(b.x), std::abs(b.y)));
    if (!near(pc.sx, a.x, sa) || !near(pc.sy, a.y, sa)) {
      fail(k) << "start (" << pc.sx << ", " << pc.sy << ") is not input point " << pc.first << " ("
              << a.x << ", " << a.y << ")";
      return report();
    }
    if (!near(pc.ex, b.x, sb) || !near(pc.ey, b.y, sb)) {
      fail(k) << "end (" << pc.ex << ", " << pc.ey << ") is not input point " << pc.last << " ("
              << b.x << ", " << b.y << ")";
      return report();
    }
    const bool inner = pc.last > pc.first + 1;
    if (inner && a.x == b.x && a.y == b.y) {
      fail(k) << "closed loop " << pc.first << " -> " << pc.last << " with inner points";
      return report();
    }

    if (!pc.arc) {
      if (pc.dir != 0) {
        fail(k) << "line with direction " << pc.dir;
        return report();
      }
    } else {
      if (pc.dir != 1 && pc.dir != -1) {
        fail(k) << "arc with direction " << pc.dir;
        return report();
      }
      const double rs = std::hypot(pc.sx - pc.cx, pc.sy - pc.cy);
      const double re = std::hypot(pc.ex - pc.cx, pc.ey - pc.cy);
      if (!(rs > 0) || !near(rs, re, std::max(rs, re))) {
        fail(k) << "radii differ: |start-c| = " << rs << ", |end-c| = " << re;
        return report();
      }
    }

    // Inner points within tol of the circle or line.
    for (std::size_t q = pc.first + 1; q < pc.last; ++q) {
      const double d =
          pc.arc ? circle_offset(pts[q].x, pts[q].y, pc.sx, pc.sy, pc.cx, pc.cy)
                 : line_offset(pts[q].x, pts[q].y, pc.sx, pc.sy, pc.ex, pc.ey);
      if (!(std::abs(d) <= lim)) {
        fail(k) << "inner point " << q << " is " << std::abs(d) << " from the "
                << (pc.arc ? "circle" : "line") << ", tol " << tol;
        return report();
      }
    }

    // Within tol of the arc itself (each point's side of the sweep).
    for (std::size_t q = pc.first + 1; q < pc.last && reach == Reach::arc; ++q) {
      const double d = arc_distance(pts[q], pc);
      if (!(d <= lim)) {
        fail(k) << "inner point " << q << " is " << d << " from the " << (pc.arc ? "arc" : "segment")
                << " (outside its sweep), tol " << tol;
        return report();
      }
    }

    // The arc's direction: it must run through the inner points.
    if (pc.arc && inner) {
      std::size_t far = pc.first + 1;
      double far_d = -1;
      for (std::size_t q = pc.first + 1; q < pc.last; ++q) {
        const double d = std::abs(line_offset(pts[q].x, pts[q].y, pc.sx, pc.sy, pc.ex, pc.ey));
        if (d > far_d) {
          far_d = d;
          far = q;
        }
      }
      if (far_d > tol) {
        const double r = std::hypot(pc.sx - pc.cx, pc.sy - pc.cy);
        const double a0 = std::atan2(pc.sy - pc.cy, pc.sx - pc.cx);
        const double a1 = std::atan2(pc.ey - pc.cy, pc.ex - pc.cx);
        const double ap = std::atan2(pts[far].y - pc.cy, pts[far].x - pc.cx);
        const double sweep = pc.dir > 0 ? wrap_2pi(a1 - a0) : wrap_2pi(a0 - a1);
        const double pos = pc.dir > 0 ? wrap_2pi(ap - a0) : wrap_2pi(a0 - ap);
        const double slack = tol / r + 1e-12;
        if (!(pos <= sweep + slack || pos >= 2 * kPi - slack)) {
          fail(k) << "direction E = " << pc.dir << " sweeps " << sweep
                  << " rad from the start, but inner point " << far << " (" << far_d
                  << " from the chord) lies at " << pos << " rad: the arc misses it";
          return report();
        }
      }
    }
  }
  if (at != n - 1) {
    why << "pieces end at index " << at << ", expected " << n - 1;
    return report();
  }
  return {};
}

VPiece line_piece(const std::vector<VPoint>& pts, std::size_t first, std::size_t last) {
  VPiece p;
  p.first = first;
  p.last = last;
  p.sx = pts[first].x;
  p.sy = pts[first].y;
  p.ex = pts[last].x;
  p.ey = pts[last].y;
  return p;
}

}  // namespace kerf_test
