#include "brute_twin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kerf_test {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Inner {
  double px, py;  // p
  double vx, vy;  // p - mid
  double a;       // |p - mid|^2 - h^2
  double b;       // (p - mid) . n
};

struct Frame {
  double ax, ay, bx, by;  // the ends
  double mx, my;  // chord midpoint
  double nx, ny;  // unit left normal of p_i -> p_j
  double h;       // half chord
};

class PairTest {
 public:
  PairTest(const std::vector<VPoint>& pts, std::size_t i, std::size_t j, double lim)
      : lim_(lim) {
    const VPoint& p = pts[i];
    const VPoint& q = pts[j];
    const double dx = q.x - p.x, dy = q.y - p.y;
    const double len = std::hypot(dx, dy);
    f_ = {p.x, p.y, q.x, q.y, (p.x + q.x) / 2, (p.y + q.y) / 2, -dy / len, dx / len, len / 2};
    for (std::size_t k = i + 1; k < j; ++k) {
      const double vx = pts[k].x - f_.mx, vy = pts[k].y - f_.my;
      inner_.push_back({pts[k].x, pts[k].y, vx, vy, vx * vx + vy * vy - f_.h * f_.h, vx * f_.nx + vy * f_.ny});
    }
  }

  // Every inner point within lim of the segment.
  bool segment_ok() const {
    for (const Inner& p : inner_) {
      const double x = p.vx * f_.ny - p.vy * f_.nx;  // along the chord
      const double d = std::abs(x) <= f_.h ? std::abs(p.b) : end_distance(p);
      if (!(d <= lim_)) return false;
    }
    // Steps longer than 2 lim go forward along it.
    double px = f_.ax, py = f_.ay;
    for (std::size_t k = 0; k <= inner_.size(); ++k) {
      const double qx = k < inner_.size() ? inner_[k].px : f_.bx;
      const double qy = k < inner_.size() ? inner_[k].py : f_.by;
      const double ex = qx - px, ey = qy - py, len = std::hypot(ex, ey);
      if (len > 2 * lim_ && ex * f_.ny - ey * f_.nx < -1e-9 * len) return false;
      px = qx;
      py = qy;
    }
    return true;
  }

  double end_distance(const Inner& p) const {
    return std::min(std::hypot(p.px - f_.ax, p.py - f_.ay), std::hypot(p.px - f_.bx, p.py - f_.by));
  }

  // Every inner point within lim of the arc of direction dir (+1 CCW) around
  // the centre at offset t: inside its sweep (plain angles), or near an end.
  // Every step between consecutive points (the ends included) longer than
  // 2 lim turns forward about the centre, by less than half a turn.
  bool arc_ok(double t, int dir) const {
    const double cx = f_.mx + t * f_.nx, cy = f_.my + t * f_.ny;
    const double a0 = std::atan2(f_.ay - cy, f_.ax - cx);
    const double sweep = wrap(dir * (std::atan2(f_.by - cy, f_.bx - cx) - a0));
    for (const Inner& p : inner_) {
      if (wrap(dir * (std::atan2(p.py - cy, p.px - cx) - a0)) <= sweep) continue;
      if (!(end_distance(p) <= lim_)) return false;
    }
    double px = f_.ax, py = f_.ay;
    for (std::size_t k = 0; k <= inner_.size(); ++k) {
      const double qx = k < inner_.size() ? inner_[k].px : f_.bx;
      const double qy = k < inner_.size() ? inner_[k].py : f_.by;
      const double ex = qx - px, ey = qy - py, len = std::hypot(ex, ey);
      const double ux = px - cx, uy = py - cy;
      if (len > 2 * lim_ && dir * (ux * ey - uy * ex) < -1e-9 * len * std::hypot(ux, uy)) return false;
      px = qx;
      py = qy;
    }
    return true;
  }

  // The centres from which the step from p to q points along the centre's
  // ray from p (the step constraint's edges): (p - c) x (q - p) = 0.
  void step_roots(std::vector<double>& out) const {
    double px = f_.ax, py = f_.ay;
    for (std::size_t k = 0; k <= inner_.size(); ++k) {
      const double qx = k < inner_.size() ? inner_[k].px : f_.bx;
      const double qy = k < inner_.size() ? inner_[k].py : f_.by;
      const double ex = qx - px, ey = qy - py;
      const double vx = px - f_.mx, vy = py - f_.my;
      const double ne = f_.nx * ey - f_.ny * ex;
      if (ne != 0) out.push_back((vx * ey - vy * ex) / ne);
      px = qx;
      py = qy;
    }
  }

  static double wrap(double a) {
    a = std::fmod(a, 2 * kPi);
    return a < 0 ? a + 2 * kPi : a;
  }

  const Frame& frame() const { return f_; }
  const std::vector<Inner>& inner() const { return inner_; }

  // A quick filter for the dense net, with the circle given by t and r: the
  // same test squared, |p - c|^2 - r^2 = A - 2 t B against (r +- lim)^2, with
  // a little slack so that it never rejects what circle_ok accepts.
  bool power_ok(double t, double r) {
    const double l = lim_ * (1 + 1e-6);
    const double hi = 2 * l * r;
    const std::size_t m = inner_.size();
    for (std::size_t s = 0; s < m; ++s) {
      const std::size_t k = s == 0 ? first_ : (s <= first_ ? s - 1 : s);
      const Inner& p = inner_[k];
      const double q = p.a - l * l - 2 * t * p.b;  // d^2 - (r^2 + l^2)
      if (q > hi || (r >= l && q < -hi)) {
        first_ = k;
        return false;
      }
    }
    return true;
  }

  // Every inner point within lim of the circle with centre offset t.
  bool circle_ok(double t) {
    if (!std::isfinite(t)) return false;
    const double r = std::sqrt(f_.h * f_.h + t * t);
    const std::size_t m = inner_.size();
    // The point that failed last goes first: it usually fails again.
    for (std::size_t s = 0; s < m; ++s) {
      const std::size_t k = s == 0 ? first_ : (s <= first_ ? s - 1 : s);
      const Inner& p = inner_[k];
      // |p - c| - r = (|p - c|^2 - r^2) / (|p - c| + r), |p - c|^2 - r^2 = A - 2 t B.
      const double ux = p.vx - t * f_.nx, uy = p.vy - t * f_.ny;
      const double d = std::sqrt(ux * ux + uy * uy);
      const double off = (p.a - 2 * t * p.b) / (d + r);
      if (!(std::abs(off) <= lim_)) {
        first_ = k;
        return false;
      }
    }
    return true;
  }

 private:
  Frame f_{};
  std::vector<Inner> inner_;
  double lim_;
  std::size_t first_ = 0;
};

// Real roots of c2 t^2 + c1 t + c0 = 0 with discriminant disc (given, since
// the caller has a cancellation-free form of it); also the vertex when the
// discriminant is slightly negative (a near-tangency), as one more candidate.
void roots(double c2, double c1, double c0, double disc, std::vector<double>& out) {
  if (disc < 0) {
    if (c2 != 0) out.push_back(-c1 / (2 * c2));
    return;
  }
  const double sq = std::sqrt(disc);
  const double q = -(c1 + (c1 >= 0 ? sq : -sq)) / 2;
  if (q != 0) out.push_back(c0 / q);
  if (c2 != 0) {
    if (q != 0) out.push_back(q / c2);
    else out.push_back(0.0);
  }
}

// cot(phi) and 1 / sin(phi) at phi = pi (s + 1/2) / samples, s = 0..samples-1
// (t = h cot(phi), r = h / sin(phi)), kept for the last sample count asked for.
struct Sample {
  double cot, csc;
};
const std::vector<Sample>& sample_table(int samples) {
  static std::vector<Sample> table;
  if (table.size() != static_cast<std::size_t>(samples)) {
    table.clear();
    for (int s = 0; s < samples; ++s) {
      const double phi = kPi * (s + 0.5) / samples;
      table.push_back({std::cos(phi) / std::sin(phi), 1 / std::sin(phi)});
    }
  }
  return table;
}

}  // namespace

TwinStats& twin_stats() {
  static TwinStats stats;
  return stats;
}

TwinCircle twin_pair(const std::vector<VPoint>& pts, std::size_t i, std::size_t j, double tol,
                     int samples) {
  TwinCircle res;
  if (j <= i + 1) {
    res.feasible = true;
    res.line = true;
    return res;
  }
  if (pts[i].x == pts[j].x && pts[i].y == pts[j].y) return res;  // closed loop

  const double lim = tol * (1 + 1e-9) + 1e-12 * scale_of(pts);
  PairTest test(pts, i, j, lim);
  if (test.segment_ok()) {
    res.feasible = true;
    res.line = true;
    return res;
  }
  const double h = test.frame().h;
  auto accept = [&](double t) {
    if (!test.circle_ok(t)) return false;
    for (const int dir : {1, -1}) {
      if (!test.arc_ok(t, dir)) continue;
      res.feasible = true;
      res.t = t;
      res.dir = dir;
      return true;
    }
    return false;
  };

  // The exact candidates: the end points of every point's allowed set.
  std::vector<double> cand{0.0};
  if (h < tol) {
    const double s = std::sqrt(tol * tol - h * h);
    cand.push_back(s);
    cand.push_back(-s);
  }
  for (const Inner& p : test.inner()) {
    // (D - 2 t B)^2 = 4 tol^2 (h^2 + t^2) with D = A - tol^2, divided by 4:
    // (B^2 - tol^2) t^2 - D B t + (D^2 / 4 - tol^2 h^2) = 0, whose
    // discriminant is tol^2 (D^2 + 4 h^2 (B^2 - tol^2)).
    const double d = p.a - tol * tol;
    const double c2 = p.b * p.b - tol * tol;
    const double c1 = -d * p.b;
    const double c0 = d * d / 4 - tol * tol * h * h;
    const double disc = tol * tol * (d * d + 4 * h * h * c2);
    roots(c2, c1, c0, disc, cand);
    // The centres from which p lies on the ray through p_i or through p_j.
    const double x = p.vx * test.frame().ny - p.vy * test.frame().nx;
    if (h + x != 0) cand.push_back(h * p.b / (h + x));
    if (h - x != 0) cand.push_back(h * p.b / (h - x));
  }
  test.step_roots(cand);
  for (double t : cand)
    if (accept(t)) return res;

  // The second net: a dense, uniform sweep of the pencil's tangent angle.
  // Finding a circle here that the roots missed means the roots are wrong.
  for (const Sample& s : sample_table(samples)) {
    const double t = h * s.cot;
    if (!test.power_ok(t, h * s.csc)) continue;
    if (accept(t)) {
      ++twin_stats().net_only;
      return res;
    }
  }
  return res;
}

TwinResult twin_min_count(const std::vector<VPoint>& pts, double tol, int samples) {
  TwinResult out;
  const std::size_t n = pts.size();
  if (n < 2) return out;
  constexpr std::size_t inf = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> best{0}, pred(n, 0);
  best.resize(n, inf);
  for (std::size_t j = 1; j < n; ++j) {
    // Starts in order of their count, so the first feasible one is optimal.
    for (std::size_t cnt = 0; cnt < j && best[j] == inf; ++cnt) {
      // Nearest first: short pieces are the cheap, likely feasible ones.
      for (std::size_t i = j; i-- > 0;) {
        if (best[i] != cnt) continue;
        if (twin_pair(pts, i, j, tol, samples).feasible) {
          best[j] = cnt + 1;
          pred[j] = i;
          break;
        }
      }
    }
  }
  out.pieces = best[n - 1];
  for (std::size_t k = n - 1; k != 0; k = pred[k]) out.path.push_back(k);
  out.path.push_back(0);
  std::reverse(out.path.begin(), out.path.end());
  return out;
}

std::vector<VPiece> twin_pieces(const std::vector<VPoint>& pts, const std::vector<std::size_t>& path,
                                double tol, int samples) {
  std::vector<VPiece> out;
  for (std::size_t k = 1; k < path.size(); ++k) {
    const std::size_t i = path[k - 1], j = path[k];
    const TwinCircle c = twin_pair(pts, i, j, tol, samples);
    VPiece p = line_piece(pts, i, j);
    if (!c.feasible || c.line) {  // an infeasible pair is left for the verifier to reject
      out.push_back(p);
      continue;
    }
    const double dx = p.ex - p.sx, dy = p.ey - p.sy;
    const double len = std::hypot(dx, dy);
    const double nx = -dy / len, ny = dx / len;
    p.arc = true;
    p.cx = (p.sx + p.ex) / 2 + c.t * nx;
    p.cy = (p.sy + p.ey) / 2 + c.t * ny;
    p.dir = c.dir;
    out.push_back(p);
  }
  return out;
}

}  // namespace kerf_test
