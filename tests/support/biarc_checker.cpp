#include "biarc_checker.hpp"

#include <cmath>

#include "arc_param.hpp"

namespace kerf_test {

namespace {

double dist(VPoint a, VPoint b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The arc (or line) from p with unit tangent t through x.
VPiece arc_from(VPoint p, VPoint t, VPoint x, std::size_t i, std::size_t j) {
  VPiece pc;
  pc.first = i;
  pc.last = j;
  pc.sx = p.x;
  pc.sy = p.y;
  pc.ex = x.x;
  pc.ey = x.y;
  const double nx = -t.y, ny = t.x;  // left normal
  const double dx = x.x - p.x, dy = x.y - p.y;
  const double side = nx * dx + ny * dy;
  const double d2 = dx * dx + dy * dy;
  if (std::abs(side) <= 1e-14 * d2 / std::max(std::sqrt(d2), 1e-300)) return pc;  // a line
  const double r = d2 / (2 * side);  // signed: > 0 turns left
  pc.arc = true;
  pc.cx = p.x + nx * r;
  pc.cy = p.y + ny * r;
  pc.dir = r > 0 ? 1 : -1;
  return pc;
}

// Does the piece meet the segment a b anywhere farther than eps from `skip`?
bool meets_except(const VPiece& pc, VPoint a, VPoint b, VPoint skip, double eps) {
  const ArcParam ap = arc_of_piece(pc);
  double t[2];
  const int m = circle_line_roots(ap, a, b, t);
  for (int k = 0; k < m; ++k) {
    if (t[k] < -1e-12 || t[k] > 1 + 1e-12) continue;
    const VPoint x{a.x + t[k] * (b.x - a.x), a.y + t[k] * (b.y - a.y)};
    if (dist(x, skip) <= eps) continue;
    const double s = arc_position(ap, x);
    if (s >= -eps && s <= ap.length + eps) return true;
  }
  return false;
}

}  // namespace

VPoint piece_tangent(const VPiece& pc, bool end) {
  const ArcParam ap = arc_of_piece(pc);
  return arc_tangent(ap, end ? ap.length : 0.0);
}

double angle_between(VPoint a, VPoint b) {
  return std::atan2(std::abs(a.x * b.y - a.y * b.x), a.x * b.x + a.y * b.y);
}

VBiarc biarc_through(VPoint p, VPoint tp, VPoint q, VPoint tq, VPoint m, std::size_t i,
                     std::size_t j) {
  VBiarc b;
  b.a1 = arc_from(p, tp, m, i, j);
  // The second arc, run backwards from q with the reversed tangent.
  VPiece back = arc_from(q, {-tq.x, -tq.y}, m, i, j);
  b.a2 = back;
  b.a2.sx = back.ex;
  b.a2.sy = back.ey;
  b.a2.ex = back.sx;
  b.a2.ey = back.sy;
  b.a2.dir = -back.dir;
  return b;
}

BandReport check_biarc(const std::vector<VPoint>& pts, const std::vector<VPoint>& tangents,
                       const BandWidths& widths, const VBiarc& b, double slack, double max_turn,
                       const BandWidths* gate_widths) {
  BandReport rep;
  auto fail = [&](const std::string& why) {
    rep.ok = false;
    rep.why = "biarc " + std::to_string(b.a1.first) + "->" + std::to_string(b.a1.last) + ": " + why;
    return rep;
  };
  const std::size_t i = b.a1.first, j = b.a1.last;
  if (!(i < j && j < pts.size()) || b.a2.first != i || b.a2.last != j) return fail("bad indices");
  const double scale = scale_of(pts);
  const double eps = 1e-9 * scale;
  if (dist({b.a1.sx, b.a1.sy}, pts[i]) > eps) return fail("does not start on its point");
  if (dist({b.a2.ex, b.a2.ey}, pts[j]) > eps) return fail("does not end on its point");
  if (dist({b.a1.ex, b.a1.ey}, {b.a2.sx, b.a2.sy}) > eps) return fail("arcs do not meet");
  for (const VPiece* pc : {&b.a1, &b.a2}) {
    if (!pc->arc) continue;
    const double r1 = dist({pc->sx, pc->sy}, {pc->cx, pc->cy});
    const double r2 = dist({pc->ex, pc->ey}, {pc->cx, pc->cy});
    if (std::abs(r1 - r2) > 1e-9 * std::max(r1, scale)) return fail("unequal radii");
  }
  // A joint on p_i or p_j (the single-circle case) leaves one part a point:
  // it has no tangent, and the other part must meet both t_i and t_j.
  auto is_point = [&](const VPiece& pc) { return !pc.arc && dist({pc.sx, pc.sy}, {pc.ex, pc.ey}) <= eps; };
  const bool p1 = is_point(b.a1), p2 = is_point(b.a2);
  if (p1 && p2) return fail("both parts are points");
  const VPoint t0 = p1 ? piece_tangent(b.a2, false) : piece_tangent(b.a1, false);
  const VPoint t1 = p2 ? piece_tangent(b.a1, true) : piece_tangent(b.a2, true);
  const VPoint tj1 = p1 ? t0 : piece_tangent(b.a1, true);
  const VPoint tj2 = p2 ? t1 : piece_tangent(b.a2, false);
  if (angle_between(t0, tangents[i]) > max_turn) return fail("start tangent is not t_i");
  if (angle_between(t1, tangents[j]) > max_turn) return fail("end tangent is not t_j");
  if (angle_between(tj1, tj2) > max_turn) return fail("corner at the joint");
  const BandWidths& gw = gate_widths != nullptr ? *gate_widths : widths;
  for (const std::size_t k : {i, j}) {
    if (!(gw.left[k] >= 0 && gw.right[k] >= 0 && gw.left[k] <= widths.left[k] * (1 + 1e-12) &&
          gw.right[k] <= widths.right[k] * (1 + 1e-12)))
      return fail("the region's width at point " + std::to_string(k) + " is not within the band's");
  }
  const BandGate gi = band_gate(pts, gw, i), gj = band_gate(pts, gw, j);
  if (t0.x * gi.fx + t0.y * gi.fy <= 0) return fail("leaves gate i backwards");
  if (t1.x * gj.fx + t1.y * gj.fy <= 0) return fail("reaches gate j backwards");
  for (const VPiece* pc : {&b.a1, &b.a2}) {
    if (meets_except(*pc, gi.left, gi.right, pts[i], eps)) return fail("meets gate i again");
    if (meets_except(*pc, gj.left, gj.right, pts[j], eps)) return fail("meets gate j again");
    double worst = 0;
    if (!arc_in_band(pts, widths, *pc, slack, &worst))
      return fail("leaves the band (" + std::to_string(worst) + ")");
    rep.worst = std::max(rep.worst, worst);
  }
  return rep;
}

BandReport check_biarc_fit(const std::vector<VPoint>& pts, const std::vector<VPoint>& tangents,
                           const BandWidths& widths, const std::vector<VBiarc>& fit, double slack,
                           double max_turn, const BandWidths* gate_widths) {
  BandReport rep;
  std::size_t at = 0;
  for (const VBiarc& b : fit) {
    if (b.a1.first != at) {
      rep.ok = false;
      rep.why = "biarcs are not contiguous at point " + std::to_string(at);
      return rep;
    }
    const BandReport one = check_biarc(pts, tangents, widths, b, slack, max_turn, gate_widths);
    if (!one.ok) return one;
    rep.worst = std::max(rep.worst, one.worst);
    at = b.a1.last;
  }
  if (at + 1 != pts.size()) {
    rep.ok = false;
    rep.why = "the biarcs stop at point " + std::to_string(at);
  }
  return rep;
}

}  // namespace kerf_test
