// Gates and the piece / fit checks of the band referee (see band_checker.hpp).
#include "band_checker.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "arc_param.hpp"

namespace kerf_test {

namespace {

constexpr double kRel = 1e-9;
constexpr double kCusp = 1e-6;

VPoint unit_edge(const std::vector<VPoint>& pts, std::size_t k) {
  const double dx = pts[k + 1].x - pts[k].x, dy = pts[k + 1].y - pts[k].y;
  const double len = std::hypot(dx, dy);
  return len > 0 ? VPoint{dx / len, dy / len} : VPoint{0, 0};
}

bool finite(const VPiece& p) {
  return std::isfinite(p.sx) && std::isfinite(p.sy) && std::isfinite(p.ex) && std::isfinite(p.ey) &&
         (!p.arc || (std::isfinite(p.cx) && std::isfinite(p.cy)));
}

// The forward normal a piece must respect where it starts (or ends) at k; at
// a cusp the edge it leaves (or arrives on) stands in for the missing gate.
VPoint forward_at(const std::vector<VPoint>& pts, const BandWidths& bw, std::size_t k, bool start) {
  const BandGate g = band_gate(pts, bw, k);
  if (!g.cusp) return {g.fx, g.fy};
  return unit_edge(pts, start ? k : k - 1);
}

}  // namespace

BandGate band_gate(const std::vector<VPoint>& pts, const BandWidths& bw, std::size_t k) {
  BandGate g;
  const std::size_t n = pts.size();
  const VPoint p = pts[k];
  double gl = bw.left[k], gr = bw.right[k];
  if (k == 0 || k == n - 1) {
    const VPoint u = unit_edge(pts, k == 0 ? 0 : n - 2);
    g.bx = -u.y;
    g.by = u.x;
  } else {
    const VPoint u0 = unit_edge(pts, k - 1), u1 = unit_edge(pts, k);
    const double sx = u0.x + u1.x, sy = u0.y + u1.y;  // |u0 + u1| = |n0 + n1|
    const double len = std::hypot(sx, sy);
    if (len < kCusp) {
      g.cusp = true;
      g.left = g.right = p;
      return g;
    }
    g.bx = -sy / len;  // unit(n0 + n1), the left normal of unit(u0 + u1)
    g.by = sx / len;
    const double cos_half = g.bx * (-u1.y) + g.by * u1.x;
    const double sin2 = std::max(0.0, 1 - cos_half * cos_half);
    const double c = (bw.left[k] - bw.right[k]) / 2, w = (bw.left[k] + bw.right[k]) / 2;
    const double root = std::sqrt(std::max(0.0, w * w - c * c * sin2));
    gl = c * cos_half + root;
    gr = -c * cos_half + root;
  }
  g.fx = g.by;  // b turned clockwise: unit(u0 + u1), towards p_{k+1}
  g.fy = -g.bx;
  g.left = {p.x + gl * g.bx, p.y + gl * g.by};
  g.right = {p.x - gr * g.bx, p.y - gr * g.by};
  return g;
}

BandReport check_band_piece(const std::vector<VPoint>& pts, const BandWidths& widths,
                            const VPiece& pc, double slack) {
  std::ostringstream why;
  why.precision(17);
  auto fail = [&]() { return BandReport{false, why.str(), -1e300}; };
  const std::size_t n = pts.size();
  if (n < 2 || widths.left.size() != n || widths.right.size() != n) {
    why << "need two or more points and one width pair per point";
    return fail();
  }
  if (!(pc.first < pc.last) || pc.last >= n) {
    why << "bad index range " << pc.first << " -> " << pc.last << " for " << n << " points";
    return fail();
  }
  if (!finite(pc)) {
    why << "non-finite coordinates";
    return fail();
  }
  const double scale = scale_of(pts);
  const VPoint a = pts[pc.first], b = pts[pc.last];
  const double sa = std::max({scale, std::abs(a.x), std::abs(a.y)});
  const double sb = std::max({scale, std::abs(b.x), std::abs(b.y)});
  if (std::hypot(pc.sx - a.x, pc.sy - a.y) > kRel * sa) {
    why << "start (" << pc.sx << ", " << pc.sy << ") is not input point " << pc.first;
    return fail();
  }
  if (std::hypot(pc.ex - b.x, pc.ey - b.y) > kRel * sb) {
    why << "end (" << pc.ex << ", " << pc.ey << ") is not input point " << pc.last;
    return fail();
  }
  if (pc.arc) {
    const double rs = std::hypot(pc.sx - pc.cx, pc.sy - pc.cy);
    const double re = std::hypot(pc.ex - pc.cx, pc.ey - pc.cy);
    if ((pc.dir != 1 && pc.dir != -1) || !(rs > 0) || std::abs(rs - re) > kRel * std::max(rs, re)) {
      why << "bad arc: direction " << pc.dir << ", radii " << rs << " and " << re;
      return fail();
    }
  } else if (pc.dir != 0) {
    why << "line with direction " << pc.dir;
    return fail();
  }
  for (std::size_t m = pc.first + 1; m < pc.last; ++m) {
    if (band_gate(pts, widths, m).cusp) {
      why << "passes through cusp vertex " << m;
      return fail();
    }
  }

  const ArcParam arc = arc_of_piece(pc);
  const VPoint t0{arc.tx, arc.ty};
  const VPoint t1 = arc_tangent(arc, arc.length);
  const VPoint f0 = forward_at(pts, widths, pc.first, true);
  const VPoint f1 = forward_at(pts, widths, pc.last, false);
  if (t0.x * f0.x + t0.y * f0.y < -kRel) {
    why << "start tangent points backwards through gate " << pc.first;
    return fail();
  }
  if (t1.x * f1.x + t1.y * f1.y < -kRel) {
    why << "end tangent arrives backwards through gate " << pc.last;
    return fail();
  }

  // Inner gates: each is cut, in order along the arc. Where the ideal gates
  // of short edges overlap, the arc may also cut a gate early (on a part that
  // reaches past its neighbours), so the rule is that some choice of cuts,
  // one per gate, increases: each gate's first cut after the previous one.
  const double along_slack = 1e-12 * (arc.length + scale);
  double prev = -along_slack;
  for (std::size_t m = pc.first + 1; m < pc.last; ++m) {
    const BandGate g = band_gate(pts, widths, m);
    double t[2];
    const int roots = circle_line_roots(arc, g.right, g.left, t);
    double cut = -1;
    bool any = false;
    for (int r = 0; r < roots; ++r) {
      if (t[r] < -kRel || t[r] > 1 + kRel) continue;
      const VPoint x{g.right.x + t[r] * (g.left.x - g.right.x),
                     g.right.y + t[r] * (g.left.y - g.right.y)};
      const double s = arc_position(arc, x);
      if (s < -along_slack || s > arc.length + along_slack) continue;
      any = true;
      if (s > prev && (cut < 0 || s < cut)) cut = std::max(s, 0.0);
    }
    if (any && cut < 0) cut = prev;  // cut, but only before: reported below
    if (cut < 0) {
      why << "does not cut gate " << m;
      return fail();
    }
    if (!(cut > prev)) {
      why << "cuts gate " << m << " at arc length " << cut << ", not after the previous gate ("
          << prev << ")";
      return fail();
    }
    prev = cut;
  }

  double worst = 0;
  if (!arc_in_band(pts, widths, pc, slack, &worst)) {
    why << "leaves the band: band value " << worst << " (slack " << slack << ")";
    BandReport r = fail();
    r.worst = worst;
    return r;
  }
  return {true, "", worst};
}

BandReport check_band_fit(const std::vector<VPoint>& pts, const BandWidths& widths,
                          const std::vector<VPiece>& pieces, double slack) {
  BandReport all;
  const std::size_t n = pts.size();
  if (n < 2 || pieces.empty()) return {false, "fewer than two points or no pieces", -1e300};
  std::size_t at = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    std::ostringstream why;
    if (pieces[k].first != at) {
      why << "piece " << k << ": starts at index " << pieces[k].first << ", expected " << at
          << " (not contiguous)";
      return {false, why.str(), all.worst};
    }
    const BandReport r = check_band_piece(pts, widths, pieces[k], slack);
    if (!r.ok) {
      why << "piece " << k << ": " << r.why;
      return {false, why.str(), std::max(all.worst, r.worst)};
    }
    all.worst = std::max(all.worst, r.worst);
    at = pieces[k].last;
  }
  if (at != n - 1) {
    std::ostringstream why;
    why << "pieces end at index " << at << ", expected " << n - 1;
    return {false, why.str(), all.worst};
  }
  return all;
}

}  // namespace kerf_test
