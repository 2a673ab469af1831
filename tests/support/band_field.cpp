// The band function and the certified checks along a piece (see band_checker.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "arc_param.hpp"
#include "band_checker.hpp"

namespace kerf_test {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxDepth = 60;
constexpr long kMaxSamples = 1L << 22;

// The per-edge term of the band function at x: min over s in [0, 1] of
// |a - s v| - (w0 + s (w1 - w0)), a convex function of s.
double edge_term(VPoint x, const std::vector<VPoint>& pts, const BandWidths& bw, std::size_t k) {
  const VPoint& p = pts[k];
  const VPoint& q = pts[k + 1];
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double len = std::hypot(dx, dy);
  const double nx = len > 0 ? -dy / len : 0, ny = len > 0 ? dx / len : 0;
  const double c0 = (bw.left[k] - bw.right[k]) / 2, c1 = (bw.left[k + 1] - bw.right[k + 1]) / 2;
  const double w0 = (bw.left[k] + bw.right[k]) / 2, w1 = (bw.left[k + 1] + bw.right[k + 1]) / 2;
  const double ax = x.x - p.x - c0 * nx, ay = x.y - p.y - c0 * ny;
  const double vx = dx + (c1 - c0) * nx, vy = dy + (c1 - c0) * ny;
  auto at = [&](double s) { return std::hypot(ax - s * vx, ay - s * vy) - (w0 + s * (w1 - w0)); };
  double best = std::min(at(0), at(1));
  const double vl = std::hypot(vx, vy);
  if (!(vl > 0)) return best;
  // With t = s |v|, alpha / beta the parts of a along / across v and
  // m = dw / |v|: the slope (t - alpha) / |a - t v^| equals m at
  // t = alpha + m |beta| / sqrt(1 - m^2); for |m| >= 1 an end is the minimum.
  const double ux = vx / vl, uy = vy / vl;
  const double alpha = ax * ux + ay * uy;
  const double beta = std::abs(ax * uy - ay * ux);
  const double m = (w1 - w0) / vl;
  if (m > -1 && m < 1) {
    const double t = alpha + m * beta / std::sqrt(1 - m * m);
    best = std::min(best, at(std::clamp(t / vl, 0.0, 1.0)));
  }
  return best;
}

// The field along a piece: per-edge terms for edges first..last-1.
struct Field {
  const std::vector<VPoint>& pts;
  const BandWidths& bw;
  std::size_t first, last;

  std::vector<double> terms(VPoint x) const {
    std::vector<double> f;
    f.reserve(last - first);
    for (std::size_t k = first; k < last; ++k) f.push_back(edge_term(x, pts, bw, k));
    return f;
  }
};

double min_of(const std::vector<double>& f) { return *std::min_element(f.begin(), f.end()); }

// An upper bound of the field over the sub-arc between two sampled ends:
// some edge's term is convex along the chord, and the sub-arc stays within
// sag of the chord (only for sub-arcs turning at most pi / 2).
double chord_bound(const ArcParam& a, double ds, const std::vector<double>& f0,
                   const std::vector<double>& f1) {
  if (std::abs(a.kappa) * ds > kPi / 2) return std::numeric_limits<double>::infinity();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < f0.size(); ++k) best = std::min(best, std::max(f0[k], f1[k]));
  return best + arc_sag(a, ds);
}

struct Span {
  double s0, s1;
  std::vector<double> f0, f1;
  int depth;
};

bool prove(const ArcParam& a, const Field& field, double slack, double* worst) {
  std::vector<double> fa = field.terms(a.s);
  std::vector<double> fb = field.terms(arc_point(a, a.length));
  double top = std::max(min_of(fa), min_of(fb));
  auto done = [&](bool ok) {
    if (worst) *worst = top;
    return ok;
  };
  if (!(top <= slack)) return done(false);
  long samples = 2;
  std::vector<Span> stack;
  stack.push_back({0, a.length, std::move(fa), std::move(fb), 0});
  while (!stack.empty()) {
    Span sp = std::move(stack.back());
    stack.pop_back();
    const double ds = sp.s1 - sp.s0;
    if (chord_bound(a, ds, sp.f0, sp.f1) <= slack) continue;
    const double mid = sp.s0 + ds / 2;
    std::vector<double> fm = field.terms(arc_point(a, mid));
    const double bm = min_of(fm);
    ++samples;
    top = std::max(top, bm);
    if (!(bm <= slack)) return done(false);
    if (bm <= slack - ds / 2) continue;
    if (sp.depth >= kMaxDepth || samples >= kMaxSamples) return done(false);
    stack.push_back({sp.s0, mid, std::move(sp.f0), fm, sp.depth + 1});
    stack.push_back({mid, sp.s1, std::move(fm), std::move(sp.f1), sp.depth + 1});
  }
  return done(true);
}

bool widths_fit(const std::vector<VPoint>& pts, const BandWidths& bw) {
  return bw.left.size() == pts.size() && bw.right.size() == pts.size();
}

}  // namespace

BandWidths symmetric_widths(std::size_t n, double tol) { return asymmetric_widths(n, tol, tol); }

BandWidths asymmetric_widths(std::size_t n, double left, double right) {
  return {std::vector<double>(n, left), std::vector<double>(n, right)};
}

BandWidths per_vertex_widths(const std::vector<double>& tol) { return {tol, tol}; }

double band_value(VPoint x, const std::vector<VPoint>& pts, const BandWidths& widths,
                  std::size_t first, std::size_t last) {
  double best = std::numeric_limits<double>::infinity();
  if (!widths_fit(pts, widths) || !(first < last) || last >= pts.size()) return best;
  for (std::size_t k = first; k < last; ++k) best = std::min(best, edge_term(x, pts, widths, k));
  return best;
}

bool arc_in_band(const std::vector<VPoint>& pts, const BandWidths& widths, const VPiece& piece,
                 double slack, double* worst) {
  if (worst) *worst = std::numeric_limits<double>::infinity();
  if (!widths_fit(pts, widths) || !(piece.first < piece.last) || piece.last >= pts.size())
    return false;
  const ArcParam a = arc_of_piece(piece);
  if (!std::isfinite(a.length) || !std::isfinite(a.kappa)) return false;
  return prove(a, Field{pts, widths, piece.first, piece.last}, slack, worst);
}

bool segment_in_band(const std::vector<VPoint>& pts, const BandWidths& widths, std::size_t first,
                     std::size_t last, VPoint a, VPoint b, double slack, double* worst) {
  VPiece line;
  line.first = first;
  line.last = last;
  line.sx = a.x;
  line.sy = a.y;
  line.ex = b.x;
  line.ey = b.y;
  return arc_in_band(pts, widths, line, slack, worst);
}

double band_piece_deviation(const std::vector<VPoint>& pts, const VPiece& piece) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!(piece.first < piece.last) || piece.last >= pts.size()) return kInf;
  const ArcParam a = arc_of_piece(piece);
  if (!std::isfinite(a.length) || !std::isfinite(a.kappa)) return kInf;
  const BandWidths zero = symmetric_widths(pts.size(), 0.0);
  const Field field{pts, zero, piece.first, piece.last};
  const std::vector<VPoint> sub(pts.begin() + static_cast<std::ptrdiff_t>(piece.first),
                                pts.begin() + static_cast<std::ptrdiff_t>(piece.last) + 1);
  const double abs_tol = 1e-12 * scale_of(sub);

  struct Node {
    double upper;
    Span span;
    bool operator<(const Node& o) const { return upper < o.upper; }
  };
  std::priority_queue<Node> open;
  std::vector<double> fa = field.terms(a.s);
  std::vector<double> fb = field.terms(arc_point(a, a.length));
  double lower = std::max(min_of(fa), min_of(fb));
  const double up0 = chord_bound(a, a.length, fa, fb);
  open.push({up0, {0, a.length, std::move(fa), std::move(fb), 0}});
  for (long pops = 0; pops < (1L << 20); ++pops) {
    if (open.top().upper <= lower * (1 + 1e-9) + abs_tol) break;
    Span sp = open.top().span;
    open.pop();
    const double ds = sp.s1 - sp.s0;
    const double mid = sp.s0 + ds / 2;
    std::vector<double> fm = field.terms(arc_point(a, mid));
    const double bm = min_of(fm);
    lower = std::max(lower, bm);
    // Each half also obeys the Lipschitz bound from its own sampled ends.
    const double half = ds / 2;
    const double u0 = std::min(chord_bound(a, half, sp.f0, fm), std::min(min_of(sp.f0), bm) + half);
    const double u1 = std::min(chord_bound(a, half, fm, sp.f1), std::min(min_of(sp.f1), bm) + half);
    open.push({u0, {sp.s0, mid, std::move(sp.f0), fm, sp.depth + 1}});
    open.push({u1, {mid, sp.s1, std::move(fm), std::move(sp.f1), sp.depth + 1}});
  }
  return std::max(open.top().upper, lower);
}

}  // namespace kerf_test
