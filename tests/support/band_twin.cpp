#include "band_twin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "arc_param.hpp"

namespace kerf_test {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kGrid = 2048;
constexpr double kDotSlack = 1e-12;

double dot(VPoint a, VPoint b) { return a.x * b.x + a.y * b.y; }
VPoint sub(VPoint a, VPoint b) { return {a.x - b.x, a.y - b.y}; }
double norm(VPoint a) { return std::hypot(a.x, a.y); }
VPoint unit(VPoint a) {
  const double l = norm(a);
  return l > 0 ? VPoint{a.x / l, a.y / l} : VPoint{0, 0};
}

bool well_formed(const BandRegion& r) {
  const std::size_t n = r.pts.size();
  return n >= 2 && r.gate_left.size() == n && r.gate_right.size() == n &&
         r.chain_left.size() == n - 1 && r.chain_right.size() == n - 1;
}

// Forward normal of gate k: across the gate, towards p_{k+1} (gate n-1: away
// from p_{n-2}). A zero-length gate (a barrier: a cusp, or a vertex whose
// band was narrowed to nothing) has no direction of its own: a piece that
// arrives there uses the edge it arrives on, a piece that leaves the edge it
// leaves on (as the checker does at a cusp).
VPoint forward_normal(const BandRegion& r, std::size_t k, bool arriving) {
  const std::size_t n = r.pts.size();
  const VPoint ahead = k + 1 < n ? sub(r.pts[k + 1], r.pts[k]) : sub(r.pts[k], r.pts[k - 1]);
  const VPoint g = sub(r.gate_left[k], r.gate_right[k]);
  if (norm(g) > 0) {
    VPoint f = unit({g.y, -g.x});
    if (dot(f, ahead) < 0) f = {-f.x, -f.y};
    return f;
  }
  if (k == 0) return unit(sub(r.pts[1], r.pts[0]));
  if (k + 1 == n) return unit(sub(r.pts[k], r.pts[k - 1]));
  return arriving ? unit(sub(r.pts[k], r.pts[k - 1])) : unit(sub(r.pts[k + 1], r.pts[k]));
}

double wrap_pi(double a) {
  a = std::fmod(a, kPi);
  if (a < 0) a += kPi;
  return a >= kPi ? 0.0 : a;
}

class PairTwin {
 public:
  PairTwin(const BandRegion& r, std::size_t i, std::size_t j) : r_(r), i_(i), j_(j) {
    p_ = r.pts[i];
    q_ = r.pts[j];
    const VPoint d = sub(q_, p_);
    h_ = norm(d) / 2;
    u_ = unit(d);
    mid_ = {(p_.x + q_.x) / 2, (p_.y + q_.y) / 2};
    touch_ = 1e-12 * scale_of(r.pts);
  }

  bool find(VPiece* out) {
    if (!(h_ > 0)) return false;  // a closed loop has no circle family here
    for (int e : {1, -1}) {
      for (double psi : candidates(e)) {
        const ArcParam a = arc(e, psi);
        if (!valid(a)) continue;
        if (out) *out = piece_of(a);
        return true;
      }
    }
    return false;
  }

 private:
  // The arc from p to q with half sweep psi, counter-clockwise for e = +1.
  ArcParam arc(int e, double psi) const {
    ArcParam a;
    a.s = p_;
    const double c = std::cos(psi), s = std::sin(psi);
    a.tx = u_.x * c + e * u_.y * s;  // u turned by -e psi
    a.ty = -e * u_.x * s + u_.y * c;
    a.kappa = e * s / h_;
    a.length = psi == 0 ? 2 * h_ : 2 * h_ * psi / s;
    return a;
  }

  // The half sweep of the circle through p, q and x, for orientation e.
  double psi_through(int e, VPoint x) const {
    const VPoint d = sub(x, mid_);
    const double den = 2 * (d.x * -u_.y + d.y * u_.x);
    if (den == 0) return 0;
    const double t = (dot(d, d) - h_ * h_) / den;  // centre offset along the left normal
    return std::atan2(h_, e * t);
  }

  std::vector<double> candidates(int e) const {
    std::vector<double> c{0.0};
    for (std::size_t k = i_; k <= j_; ++k) {
      c.push_back(psi_through(e, r_.gate_left[k]));
      c.push_back(psi_through(e, r_.gate_right[k]));
      if (k == j_) break;
      for (const VPoint& v : r_.chain_left[k]) c.push_back(psi_through(e, v));
      for (const VPoint& v : r_.chain_right[k]) c.push_back(psi_through(e, v));
    }
    const double ua = std::atan2(u_.y, u_.x);
    for (std::size_t k : {i_, j_}) {
      const VPoint g = sub(r_.gate_left[k], r_.gate_right[k]);
      if (norm(g) == 0) continue;
      const double phi = std::atan2(g.y, g.x) - ua;
      c.push_back(wrap_pi(-e * phi));  // start tangent along the gate
      c.push_back(wrap_pi(e * phi));   // end tangent along the gate
    }
    for (double& v : c) v = wrap_pi(v);
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    const std::size_t m = c.size();
    for (std::size_t k = 0; k < m; ++k) c.push_back(((k + 1 < m ? c[k + 1] : kPi) + c[k]) / 2);
    for (int g = 0; g < kGrid; ++g) c.push_back(kPi * g / kGrid);
    return c;
  }

  bool valid(const ArcParam& a) const {
    // (c) the ends reach p and q from the correct sides.
    const VPoint t0{a.tx, a.ty};
    const double tu = dot(t0, u_);
    const VPoint t1{2 * tu * u_.x - t0.x, 2 * tu * u_.y - t0.y};  // t0 mirrored on the chord
    if (dot(t0, forward_normal(r_, i_, false)) < -kDotSlack) return false;
    if (dot(t1, forward_normal(r_, j_, true)) < -kDotSlack) return false;
    // (a) each inner gate cut once, on the arc, moving forward.
    for (std::size_t m = i_ + 1; m < j_; ++m)
      if (!stabs(a, m)) return false;
    // (b) no chain segment of the cells crossed, and the arc never leaves R
    // (which also catches an arc that leaves through a chain vertex).
    for (std::size_t k = i_; k < j_; ++k)
      if (crosses(a, r_.chain_left[k]) || crosses(a, r_.chain_right[k])) return false;
    return stays_inside(a);
  }

  bool stabs(const ArcParam& a, std::size_t m) const {
    const VPoint g0 = r_.gate_right[m], g1 = r_.gate_left[m];
    const double glen = norm(sub(g1, g0));
    double t[2];
    const int roots = circle_line_roots(a, g0, g1, t);
    const double eps = 1e-12;
    int hits = 0;
    double hit = 0;
    for (int k = 0; k < roots; ++k) {
      if (t[k] < -eps || t[k] > 1 + eps) continue;
      ++hits;
      hit = t[k];
    }
    // Two roots that coincide are a tangent contact: the arc does not cross.
    if (hits != 1 || (roots == 2 && std::abs(t[1] - t[0]) * glen <= touch_)) return false;
    const VPoint x{g0.x + hit * (g1.x - g0.x), g0.y + hit * (g1.y - g0.y)};
    const double s = arc_position(a, x);
    if (s < -touch_ || s > a.length + touch_) return false;
    return dot(arc_tangent(a, s), forward_normal(r_, m, false)) > 0;
  }

  bool crosses(const ArcParam& a, const std::vector<VPoint>& chain) const {
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      const VPoint s0 = chain[k], s1 = chain[k + 1];
      const double len = norm(sub(s1, s0));
      if (!(len > 0)) continue;
      double t[2];
      const int roots = circle_line_roots(a, s0, s1, t);
      if (roots == 2 && a.kappa != 0) {
        // How far the circle dips beyond the line between the two roots.
        const double half = std::abs(t[1] - t[0]) * len / 2;
        const double r = 1 / std::abs(a.kappa);
        const double depth = half * half / (r + std::sqrt(std::max(0.0, r * r - half * half)));
        if (depth < touch_) continue;
      }
      for (int m = 0; m < roots; ++m) {
        if (t[m] * len < touch_ || (1 - t[m]) * len < touch_) continue;
        const VPoint x{s0.x + t[m] * (s1.x - s0.x), s0.y + t[m] * (s1.y - s0.y)};
        if (norm(sub(x, p_)) < touch_ || norm(sub(x, q_)) < touch_) continue;
        const double s = arc_position(a, x);
        if (s >= 0 && s <= a.length) return true;
      }
    }
    return false;
  }

  // Splits the arc at every point where it meets R's boundary between gates
  // i and j (both chains of cells i..j-1 and the end gates) and requires the
  // middle of each part to lie in one of those cells (or on its outline).
  bool stays_inside(const ArcParam& a) const {
    std::vector<double> cuts{0.0, a.length};
    auto add_segment = [&](VPoint s0, VPoint s1) {
      double t[2];
      const int roots = circle_line_roots(a, s0, s1, t);
      for (int m = 0; m < roots; ++m) {
        // A contact at a segment's end may come out a rounding step outside.
        if (t[m] < -1e-9 || t[m] > 1 + 1e-9) continue;
        const double tm = std::clamp(t[m], 0.0, 1.0);
        const double s = arc_position(a, {s0.x + tm * (s1.x - s0.x), s0.y + tm * (s1.y - s0.y)});
        if (s > 0 && s < a.length) cuts.push_back(s);
      }
    };
    for (std::size_t k = i_; k < j_; ++k)
      for (const auto* chain : {&r_.chain_left[k], &r_.chain_right[k]})
        for (std::size_t t = 0; t + 1 < chain->size(); ++t) add_segment((*chain)[t], (*chain)[t + 1]);
    add_segment(r_.gate_left[i_], r_.gate_right[i_]);
    add_segment(r_.gate_left[j_], r_.gate_right[j_]);
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      if (cuts[c + 1] - cuts[c] <= touch_) continue;
      if (!in_region(arc_point(a, (cuts[c] + cuts[c + 1]) / 2))) return false;
    }
    return true;
  }

  // In (or within touch_ of) the outline of a cell i..j-1: its left chain,
  // then its right chain backwards.
  bool in_region(VPoint x) const {
    for (std::size_t k = i_; k < j_; ++k) {
      std::vector<VPoint> poly = r_.chain_left[k];
      poly.insert(poly.end(), r_.chain_right[k].rbegin(), r_.chain_right[k].rend());
      int winding = 0;
      bool on_edge = false;
      for (std::size_t t = 0; t < poly.size(); ++t) {
        const VPoint u = poly[t], v = poly[(t + 1) % poly.size()];
        const VPoint e = sub(v, u);
        const double len2 = dot(e, e);
        const double f = len2 > 0 ? std::clamp(dot(sub(x, u), e) / len2, 0.0, 1.0) : 0.0;
        if (norm(sub(x, {u.x + f * e.x, u.y + f * e.y})) <= touch_) on_edge = true;
        const double side = e.x * (x.y - u.y) - e.y * (x.x - u.x);
        if (u.y <= x.y && v.y > x.y && side > 0) ++winding;
        if (u.y > x.y && v.y <= x.y && side < 0) --winding;
      }
      if (on_edge || winding != 0) return true;
    }
    return false;
  }

  VPiece piece_of(const ArcParam& a) const {
    VPiece pc = line_piece(r_.pts, i_, j_);
    if (a.kappa == 0) return pc;
    pc.arc = true;
    pc.cx = p_.x - a.ty / a.kappa;  // s + N / kappa, N the left normal of T
    pc.cy = p_.y + a.tx / a.kappa;
    pc.dir = a.kappa > 0 ? 1 : -1;
    return pc;
  }

  const BandRegion& r_;
  std::size_t i_, j_;
  VPoint p_, q_, mid_, u_;
  double h_ = 0, touch_ = 0;
};

}  // namespace

bool twin_pair_valid(const BandRegion& region, std::size_t i, std::size_t j, VPiece* piece_out) {
  if (!well_formed(region) || !(i < j) || j >= region.pts.size()) return false;
  return PairTwin(region, i, j).find(piece_out);
}

int twin_min_pieces(const BandRegion& region, std::vector<VPiece>* pieces_out) {
  if (!well_formed(region)) return -1;
  const std::size_t n = region.pts.size();
  constexpr int kNone = std::numeric_limits<int>::max();
  std::vector<int> best{0};  // best[0] = 0: no pieces to reach p_0
  best.resize(n, kNone);
  std::vector<VPiece> via(n);
  for (std::size_t j = 1; j < n; ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      if (best[i] == kNone || best[i] + 1 >= best[j]) continue;
      VPiece pc;
      if (twin_pair_valid(region, i, j, &pc)) {
        best[j] = best[i] + 1;
        via[j] = pc;
      }
    }
  }
  if (best[n - 1] == kNone) return -1;
  if (pieces_out) {
    pieces_out->clear();
    for (std::size_t at = n - 1; at > 0; at = via[at].first) pieces_out->push_back(via[at]);
    std::reverse(pieces_out->begin(), pieces_out->end());
  }
  return best[n - 1];
}

}  // namespace kerf_test
