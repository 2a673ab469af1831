// Fuzz bytes to a fitter's input, as the point-file reader would hand it
// over: 2..kMaxPoints finite points on a grid of `unit` (so the numbers stay
// well inside double's range, the scale varies over six decades), consecutive
// duplicates dropped, and a tolerance from unit/64 to 4 units.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

#include "verifier.hpp"

namespace kerf_fuzz {

inline constexpr std::size_t kMaxPoints = 48;

struct FitInput {
  std::vector<kerf_test::VPoint> pts;
  double tol = 0;
  double unit = 0;
};

// Tolerances no fitter may accept, and extreme ones it must either handle
// or refuse cleanly.
inline constexpr double kBadTols[] = {0.0, -0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                                      HUGE_VAL, -HUGE_VAL};
inline constexpr double kExtremeTols[] = {5e-324, 1e-300, 1e-12, 1e300, 1.7976931348623157e308};

enum class TolKind { normal, bad, extreme };

// False when the bytes do not make two distinct points.
inline bool decode_points(FuzzedDataProvider& in, FitInput& out, TolKind* kind = nullptr) {
  out.unit = std::ldexp(1.0, in.ConsumeIntegralInRange<int>(-10, 10));
  out.tol = out.unit * (1 + in.ConsumeIntegral<std::uint8_t>()) / 64.0;
  if (kind != nullptr) {  // one input in 16 gets a bad or extreme tol
    const std::uint8_t pick = in.ConsumeIntegral<std::uint8_t>();
    *kind = TolKind::normal;
    if (pick >= 0xF0 && pick < 0xF6) {
      *kind = TolKind::bad;
      out.tol = kBadTols[pick - 0xF0];
    } else if (pick >= 0xF6 && pick < 0xFB) {
      *kind = TolKind::extreme;
      out.tol = kExtremeTols[pick - 0xF6];
    }
  }
  const std::size_t n = in.ConsumeIntegralInRange<std::size_t>(2, kMaxPoints);
  // Points as small steps from the last one (paths are mostly smooth) or,
  // with the high bit of the first byte, a jump anywhere in +-1000 units.
  double x = 0, y = 0;
  for (std::size_t k = 0; k < n && in.remaining_bytes() >= 2; ++k) {
    const std::uint8_t mode = in.ConsumeIntegral<std::uint8_t>();
    if (mode & 0x80) {
      x = in.ConsumeIntegralInRange<int>(-1000, 1000);
      y = in.ConsumeIntegralInRange<int>(-1000, 1000);
    } else {
      x += in.ConsumeIntegralInRange<int>(-16, 16);
      y += (mode & 0x3F) - 32;
    }
    const kerf_test::VPoint p{x * out.unit, y * out.unit};
    if (!out.pts.empty() && out.pts.back().x == p.x && out.pts.back().y == p.y) continue;
    out.pts.push_back(p);
  }
  return out.pts.size() >= 2;
}

// With KERF_FUZZ_DUMP set (replaying a reproducer), prints the decoded input
// as a point file for `kerf fit` and the tests: "# tol T", then "x y" lines.
inline void dump_points(const FitInput& f) {
  if (std::getenv("KERF_FUZZ_DUMP") == nullptr) return;
  std::printf("# tol %.17g\n", f.tol);
  for (const auto& p : f.pts) std::printf("%.17g %.17g\n", p.x, p.y);
  std::fflush(stdout);
}

// With KERF_FUZZ_DUMP set, prints the fitted pieces too.
inline void dump_pieces(const std::vector<kerf_test::VPiece>& pieces) {
  if (std::getenv("KERF_FUZZ_DUMP") == nullptr) return;
  for (const auto& p : pieces)
    std::printf("# piece %zu..%zu %s (%.17g,%.17g) (%.17g,%.17g) (%.17g,%.17g) %d\n", p.first, p.last,
                p.arc ? "A" : "L", p.sx, p.sy, p.ex, p.ey, p.cx, p.cy, p.dir);
  std::fflush(stdout);
}

// True when some piece's points turn by more than 90 degrees at an inner point.
inline bool piece_doubles_back(const std::vector<kerf_test::VPoint>& p,
                               const std::vector<kerf_test::VPiece>& pieces) {
  for (const auto& pc : pieces)
    for (std::size_t k = pc.first + 1; k < pc.last; ++k) {
      const double ax = p[k].x - p[k - 1].x, ay = p[k].y - p[k - 1].y;
      const double bx = p[k + 1].x - p[k].x, by = p[k + 1].y - p[k].y;
      if (ax * bx + ay * by < 0) return true;
    }
  return false;
}

// The slack the unit tests give the referee: rounding, not geometry.
inline double slack_for(const std::vector<kerf_test::VPoint>& p) {
  return 1e-9 * kerf_test::scale_of(p) + 1e-12;
}

}  // namespace kerf_fuzz
