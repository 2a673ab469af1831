// The greedy baseline against which kerf's fewest-pieces search is measured:
// ArcWelder's rule, "extend the arc while every point fits, stop at the first
// failure", with kerf's own exact pair test (vertex: every inner point
// within tol of a circle through the ends, fit/vertex/pair.hpp; band: a valid
// arc in the tolerance region, band_pair_valid). Only the search differs, so
// optimal <= greedy always, and the gap is what the search buys.
#pragma once

#include <cstdint>
#include <vector>

#include "io/band_storage.hpp"
#include "io/fit_storage.hpp"
#include "kerf/fit/band.hpp"
#include "kerf/fit/fit.hpp"
#include "kerf/fit/vertex/pair.hpp"

namespace kerf_test {

enum class WeldRule { vertex, band };

// The polyline without consecutive repeats (the fitters refuse them).
inline std::vector<kerf::Vec2<double>> distinct_points(const std::vector<kerf::Vec2<double>>& in) {
  std::vector<kerf::Vec2<double>> p;
  for (const kerf::Vec2<double>& v : in)
    if (p.empty() || !(p.back() == v)) p.push_back(v);
  return p;
}

// Pieces of the greedy welder: from each start, the longest run of points
// reached before the first pair that fails; a pair of neighbours is a line.
// p: distinct points, at least 2.
inline std::uint32_t greedy_pieces(const std::vector<kerf::Vec2<double>>& p, double tol, WeldRule rule) {
  const auto n = static_cast<std::uint32_t>(p.size());
  std::vector<kerf::fit::Interval<double>> a(kerf::fit::workspace_intervals(n)), b(a.size());
  kerf::fit::AngleSet<double> set({a.data(), a.size()}, {b.data(), b.size()});
  kerf::io::BandStorage storage(rule == WeldRule::band ? n : 0);
  std::vector<kerf::fit::BandWidth<double>> widths(rule == WeldRule::band ? n : 0, {tol, tol});
  kerf::fit::BandRegion<double> region;
  if (rule == WeldRule::band) {
    const auto r = kerf::fit::band_region<double>({p.data(), n}, {widths.data(), n}, storage.workspace());
    if (!r.ok()) return 0;
    region = r.value();
  }
  auto fits = [&](std::uint32_t i, std::uint32_t j) {
    return rule == WeldRule::vertex ? kerf::fit::vertex_pair_set(p.data(), i, j, tol, set)
                                    : kerf::fit::band_pair_valid<double>(region, i, j, nullptr);
  };
  std::uint32_t pieces = 0;
  for (std::uint32_t i = 0; i + 1 < n; ++pieces) {
    std::uint32_t j = i + 1;
    while (j + 1 < n && fits(i, j + 1)) ++j;
    i = j;
  }
  return pieces;
}

// Pieces of kerf's fewest-pieces fit with the same pair test; 0 on failure.
inline std::uint32_t optimal_pieces(const std::vector<kerf::Vec2<double>>& p, double tol, WeldRule rule) {
  const std::size_t n = p.size();
  if (rule == WeldRule::vertex) {
    kerf::io::FitStorage storage(n);
    const auto r = kerf::fit::count_min<double>({p.data(), n}, tol, kerf::fit::Method::optimal, storage.workspace());
    return r.ok() ? r.value() : 0;
  }
  kerf::io::BandStorage storage(n);
  const std::vector<kerf::fit::BandWidth<double>> widths(n, {tol, tol});
  const auto r = kerf::fit::count_band_min<double>({p.data(), n}, {widths.data(), n}, storage.workspace());
  return r.ok() ? r.value() : 0;
}

}  // namespace kerf_test
