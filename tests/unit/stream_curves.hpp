// Test inputs shared by the streaming tests: the repo's test curves and a
// smooth random curve (the heading takes a random walk, plus noise).
#pragma once

#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "kerf/geom/vec2.hpp"

namespace kerf_test {

inline std::vector<kerf::Vec2<double>> load_curve(const std::string& name) {
  std::ifstream in(std::string(KERF_TEST_DATA_DIR) + "/curves/" + name);
  std::vector<kerf::Vec2<double>> p;
  double x, y;
  while (in >> x >> y) p.push_back({x, y});
  return p;
}

inline std::vector<kerf::Vec2<double>> random_curve(unsigned seed, std::size_t n) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> turn(0.0, 0.08);
  std::uniform_real_distribution<double> noise(-0.002, 0.002);
  std::vector<kerf::Vec2<double>> p;
  double x = 0, y = 0, h = 0, k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    p.push_back({x + noise(rng), y + noise(rng)});
    k = 0.9 * k + turn(rng);
    h += k * 0.1;
    x += std::cos(h);
    y += std::sin(h);
  }
  return p;
}

}  // namespace kerf_test
