#include "biarc_twin.hpp"

#include <cmath>

#include "arc_param.hpp"

namespace kerf_test {

namespace {

constexpr double kPi = 3.14159265358979323846;

double dist(VPoint a, VPoint b) { return std::hypot(a.x - b.x, a.y - b.y); }

bool meets(const VPiece& pc, VPoint a, VPoint b, VPoint skip, double eps) {
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

bool inside_region(const BandRegion& r, const VBiarc& b, std::size_t i, std::size_t j, double eps) {
  const VPoint pi = r.pts[i], pj = r.pts[j];
  auto hit = [&](VPoint a, VPoint c) { return meets(b.a1, a, c, pi, eps) || meets(b.a2, a, c, pj, eps); };
  if (hit(r.gate_left[i], r.gate_right[i]) || hit(r.gate_left[j], r.gate_right[j])) return false;
  for (std::size_t k = i; k < j; ++k)
    for (const auto* chain : {&r.chain_left[k], &r.chain_right[k]})
      for (std::size_t q = 0; q + 1 < chain->size(); ++q)
        if (hit((*chain)[q], (*chain)[q + 1])) return false;
  return true;
}

}  // namespace

bool BiarcTwin::pair_valid(std::size_t i, std::size_t j, VBiarc* out) const {
  const std::vector<VPoint>& p = region.pts;
  const double scale = scale_of(p);
  const double eps = 1e-9 * scale;
  for (std::size_t k = i + 1; k < j; ++k)
    if (dist(region.gate_left[k], region.gate_right[k]) == 0) return false;
  const BandGate gi = band_gate(p, widths, i), gj = band_gate(p, widths, j);
  const VPoint ti = tangents[i], tj = tangents[j];
  if (ti.x * gi.fx + ti.y * gi.fy <= 0 || tj.x * gj.fx + tj.y * gj.fy <= 0) return false;
  const VPoint a = p[i], c = p[j];
  const double dx = c.x - a.x, dy = c.y - a.y;
  const double gamma = std::atan2(dy, dx);
  const double tau = gamma + (std::atan2(ti.y, ti.x) - std::atan2(tj.y, tj.x)) / 2;
  const double nx = -std::sin(tau), ny = std::cos(tau);
  const double side = nx * dx + ny * dy;
  const bool line = std::abs(side) <= 1e-12 * std::hypot(dx, dy);
  const double rr = line ? 0 : (dx * dx + dy * dy) / (2 * side);
  const VPoint centre{a.x + nx * rr, a.y + ny * rr};
  const double start = std::atan2(a.y - centre.y, a.x - centre.x);
  const double slack = 1e-9 * scale + 1e-12;
  for (int q = 0; q < samples; ++q) {
    const double x = (q + 0.5) / samples;
    VPoint m;
    if (line) {
      const double u = std::tan(kPi * (x - 0.5)) + 0.5;
      m = {a.x + u * dx, a.y + u * dy};
    } else {
      const double th = start + 2 * kPi * x;
      m = {centre.x + std::abs(rr) * std::cos(th), centre.y + std::abs(rr) * std::sin(th)};
    }
    if (dist(m, a) <= 1e-6 * scale || dist(m, c) <= 1e-6 * scale) continue;
    const VBiarc b = biarc_through(a, ti, c, tj, m, i, j);
    if (!inside_region(region, b, i, j, eps)) continue;
    if (!check_biarc(p, tangents, widths, b, slack, 1e-7).ok) continue;
    if (out != nullptr) *out = b;
    return true;
  }
  return false;
}

int BiarcTwin::min_biarcs(std::vector<VBiarc>* out) const {
  const std::size_t n = region.pts.size();
  if (n < 2) return -1;
  std::vector<int> best{0};  // (built up, not indexed: GCC 12 sees a null store otherwise)
  best.resize(n, -1);
  std::vector<std::size_t> from(n, 0);
  for (std::size_t j = 1; j < n; ++j)
    for (std::size_t i = 0; i < j; ++i)
      if (best[i] >= 0 && (best[j] < 0 || best[i] + 1 < best[j]) && pair_valid(i, j)) {
        best[j] = best[i] + 1;
        from[j] = i;
      }
  if (best[n - 1] >= 0 && out != nullptr) {
    out->assign(static_cast<std::size_t>(best[n - 1]), {});
    std::size_t j = n - 1;
    for (int k = best[n - 1]; k-- > 0;) {
      pair_valid(from[j], j, &(*out)[static_cast<std::size_t>(k)]);
      j = from[j];
    }
  }
  return best[n - 1];
}

}  // namespace kerf_test
