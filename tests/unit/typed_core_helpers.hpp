// Shared by the typed core tests: the scalar types the core is built for,
// conversions to and from double, and vector-backed fitter storage.
#pragma once

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
