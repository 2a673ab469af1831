// Shared pieces of the fit benchmarks: the test curve and the growth fit.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "kerf/geom/vec2.hpp"

namespace kerf_bench {

constexpr double kAmplitude = 50.0;
constexpr double kPeriod = 200.0;

// n points on y = A sin(2 pi x / P) with x spacing dx.
inline std::vector<kerf::Vec2<double>> sine(std::size_t n, double dx) {
  std::vector<kerf::Vec2<double>> p(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = static_cast<double>(k) * dx;
    p[k] = {x, kAmplitude * std::sin(2.0 * M_PI * x / kPeriod)};
  }
  return p;
}

// Least-squares slope of log(t) against log(n).
inline double growth_exponent(const std::vector<double>& n, const std::vector<double>& t) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = static_cast<double>(n.size());
  for (std::size_t k = 0; k < n.size(); ++k) {
    const double x = std::log(n[k]);
    const double y = std::log(t[k]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

}  // namespace kerf_bench
