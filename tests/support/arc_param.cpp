#include "arc_param.hpp"

#include <cmath>

namespace kerf_test {

namespace {

constexpr double kPi = 3.14159265358979323846;

// sin(z) / z without the cancellation near 0.
double sinc(double z) {
  if (std::abs(z) < 1e-4) return 1 - z * z / 6;
  return std::sin(z) / z;
}

// atan(z) / z, for z >= 0.
double atan_ratio(double z) {
  if (z < 1e-8) return 1 - z * z / 3;
  return std::atan(z) / z;
}

}  // namespace

ArcParam arc_of_piece(const VPiece& pc) {
  ArcParam a;
  a.s = {pc.sx, pc.sy};
  if (!pc.arc) {
    const double dx = pc.ex - pc.sx, dy = pc.ey - pc.sy;
    const double len = std::hypot(dx, dy);
    if (len > 0) {
      a.tx = dx / len;
      a.ty = dy / len;
    }
    a.length = len;
    return a;
  }
  const double vx = pc.sx - pc.cx, vy = pc.sy - pc.cy;
  const double r = std::hypot(vx, vy);
  const double e = pc.dir >= 0 ? 1.0 : -1.0;
  a.tx = -e * vy / r;
  a.ty = e * vx / r;
  a.kappa = e / r;
  a.length = arc_position(a, {pc.ex, pc.ey});
  // A piece that ends where it starts is the full circle.
  if (a.length == 0 && pc.ex == pc.sx && pc.ey == pc.sy) a.length = 2 * kPi * r;
  return a;
}

VPoint arc_point(const ArcParam& a, double sigma) {
  const double ks = a.kappa * sigma;
  const double along = sigma * sinc(ks);                       // sin(k s) / k
  const double half = sinc(ks / 2);
  const double across = a.kappa * sigma * sigma / 2 * half * half;  // (1 - cos(k s)) / k
  return {a.s.x + a.tx * along - a.ty * across, a.s.y + a.ty * along + a.tx * across};
}

VPoint arc_tangent(const ArcParam& a, double sigma) {
  const double c = std::cos(a.kappa * sigma), s = std::sin(a.kappa * sigma);
  return {a.tx * c - a.ty * s, a.ty * c + a.tx * s};
}

double arc_sag(const ArcParam& a, double ds) {
  const double q = a.kappa * ds / 4;
  const double sq = sinc(q);
  // 2 sin^2(k ds / 4) / |k|
  return std::abs(a.kappa) * ds * ds / 8 * sq * sq;
}

double arc_position(const ArcParam& a, VPoint x) {
  const double vx = x.x - a.s.x, vy = x.y - a.s.y;
  const double along = vx * a.tx + vy * a.ty;
  if (a.kappa == 0) return along;
  // Tangent-chord angle: the chord to x makes half the swept angle with T.
  const double v2 = vx * vx + vy * vy;
  const double k = std::abs(a.kappa);
  const double across = k * v2 / 2;
  if (along > 0) return v2 / along * atan_ratio(across / along);
  return 2 * std::atan2(across, along) / k;
}

int circle_line_roots(const ArcParam& a, VPoint p, VPoint q, double t[2]) {
  // x on the circle iff k |x - s|^2 - 2 (x - s).N = 0; x = p + t d.
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double ax = p.x - a.s.x, ay = p.y - a.s.y;
  const double nx = -a.ty, ny = a.tx;
  const double k = a.kappa;
  const double qa = k * (dx * dx + dy * dy);
  const double qb = 2 * k * (ax * dx + ay * dy) - 2 * (dx * nx + dy * ny);
  const double qc = k * (ax * ax + ay * ay) - 2 * (ax * nx + ay * ny);
  if (qa == 0) {
    if (qb == 0) return 0;
    t[0] = -qc / qb;
    return 1;
  }
  const double disc = qb * qb - 4 * qa * qc;
  if (disc < 0) return 0;
  const double root = std::sqrt(disc);
  const double m = -(qb + (qb >= 0 ? root : -root)) / 2;
  if (m == 0) {  // qb = 0 and qc = 0: a double root at 0
    t[0] = t[1] = 0;
    return 2;
  }
  const double r1 = m / qa, r2 = qc / m;
  t[0] = r1 < r2 ? r1 : r2;
  t[1] = r1 < r2 ? r2 : r1;
  return 2;
}

}  // namespace kerf_test
