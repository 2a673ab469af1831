// Small builders for the tests of the band referee (tests/support).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "band_checker.hpp"
#include "band_twin.hpp"
#include "verifier.hpp"

namespace kerf_test {

// Points x = 0, step, 2 step, ... on the x axis.
inline std::vector<VPoint> straight_points(std::size_t n, double step = 1.0) {
  std::vector<VPoint> p;
  for (std::size_t k = 0; k < n; ++k) p.push_back({step * static_cast<double>(k), 0.0});
  return p;
}

// The arc from pts[first] to pts[last] whose middle lies sag to the left of
// the chord (sag < 0: to the right); sag = 0 gives the line.
inline VPiece bulge_piece(const std::vector<VPoint>& pts, std::size_t first, std::size_t last,
                          double sag) {
  VPiece pc = line_piece(pts, first, last);
  if (sag == 0) return pc;
  const double dx = pc.ex - pc.sx, dy = pc.ey - pc.sy;
  const double len = std::hypot(dx, dy);
  const double h = len / 2, s = std::abs(sag);
  const double r = (h * h + s * s) / (2 * s);
  const double nx = -dy / len, ny = dx / len;
  const double side = sag > 0 ? 1.0 : -1.0;
  const double off = sag - side * r;  // the centre's offset along the left normal
  pc.arc = true;
  pc.cx = (pc.sx + pc.ex) / 2 + off * nx;
  pc.cy = (pc.sy + pc.ey) / 2 + off * ny;
  pc.dir = sag > 0 ? -1 : 1;  // a bulge to the left turns right
  return pc;
}

// The same piece moved by (dx, dy): its ends leave the input points.
inline VPiece shifted(VPiece pc, double dx, double dy) {
  pc.sx += dx;
  pc.ex += dx;
  pc.cx += dx;
  pc.sy += dy;
  pc.ey += dy;
  pc.cy += dy;
  return pc;
}

// The region of the ideal gates with straight chains between gate ends.
inline BandRegion ideal_region(const std::vector<VPoint>& pts, const BandWidths& w) {
  BandRegion r;
  r.pts = pts;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const BandGate g = band_gate(pts, w, k);
    r.gate_left.push_back(g.left);
    r.gate_right.push_back(g.right);
  }
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    r.chain_left.push_back({r.gate_left[k], r.gate_left[k + 1]});
    r.chain_right.push_back({r.gate_right[k], r.gate_right[k + 1]});
  }
  return r;
}

}  // namespace kerf_test
