// Shared by the typed core tests: the scalar types the core is built for,
// conversions to and from double, and vector-backed fitter storage.
#pragma once

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "kerf/core/fixed_convert.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::test {

template <class S>
S from_d(double v) {
  if constexpr (__is_same(S, Fixed)) return fixed_from_double(v);
  else return v;
}
template <class S>
double to_d(S v) {
  if constexpr (__is_same(S, Fixed)) return to_double(v);
  else return v;
}
template <class S>
Vec2<double> to_d(Vec2<S> v) { return {to_d(v.x), to_d(v.y)}; }
template <class S>
Vec2<S> from_d(Vec2<double> v) { return {from_d<S>(v.x), from_d<S>(v.y)}; }

template <class S>
Segment<double> to_d(const Segment<S>& s) {
  return {s.kind, to_d(s.start), to_d(s.end), to_d(s.centre), s.dir};
}

inline std::vector<Vec2<double>> load_curve(const std::string& name) {
  std::ifstream in(std::string(KERF_TEST_DATA_DIR) + "/curves/" + name);
  std::vector<Vec2<double>> p;
  double x, y;
  while (in >> x >> y) p.push_back({x, y});
  return p;
}

// A NACA 4-digit profile ("2412": 2 % camber at 40 % chord, 12 % thick) of
// `chord` mm, n points (n even) at cosine spacing: trailing edge, upper side,
// the leading edge at (0, 0), lower side, back to the trailing edge. Its nose
// has small radii far from the origin against the chord's 300 mm.
inline std::vector<Vec2<double>> naca4(const char* code, double chord = 300.0, std::size_t n = 250) {
  const double m = (code[0] - '0') / 100.0, p = (code[1] - '0') / 10.0;
  const double t = ((code[2] - '0') * 10 + (code[3] - '0')) / 100.0;
  const std::size_t half = n / 2 + 1;  // stations from the nose to the tail
  auto at = [&](std::size_t i, bool upper) {
    const double x = (1 - std::cos(M_PI * double(i) / double(half - 1))) / 2;
    const double yt = 5 * t * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x -
                               0.1015 * x * x * x * x);
    double yc = 0, dy = 0;
    if (m > 0 && x < p) yc = m / (p * p) * (2 * p * x - x * x), dy = 2 * m / (p * p) * (p - x);
    else if (m > 0) yc = m / ((1 - p) * (1 - p)) * (1 - 2 * p + 2 * p * x - x * x), dy = 2 * m / ((1 - p) * (1 - p)) * (p - x);
    const double th = std::atan(dy), s = upper ? 1 : -1;
    return Vec2<double>{chord * (x - s * yt * std::sin(th)), chord * (yc + s * yt * std::cos(th))};
  };
  std::vector<Vec2<double>> pts;
  for (std::size_t i = half; i-- > 0;) pts.push_back(at(i, true));
  for (std::size_t i = 1; i < half && pts.size() < n; ++i) pts.push_back(at(i, false));
  return pts;
}

// Fitter storage for n points in vectors (the tests may allocate).
template <class S>
struct FitBuffers {
  explicit FitBuffers(std::size_t n)
      : words(fit::workspace_words(n)), intervals(fit::workspace_intervals(n)),
        points(fit::workspace_points(n)), pieces(n) {}
  fit::Workspace<S> ws() {
    return {{words.data(), words.size()}, {intervals.data(), intervals.size()},
            {points.data(), points.size()}};
  }
  Span<fit::Piece<S>> out() { return {pieces.data(), pieces.size()}; }
  std::vector<std::uint32_t> words;
  std::vector<fit::Interval<S>> intervals;
  std::vector<Vec2<S>> points;
  std::vector<fit::Piece<S>> pieces;
};

}  // namespace kerf::test
