// Inputs shared by the tests that check the band pair test pair by pair
// (test_band_pair_shortcuts.cpp, test_band_start_region.cpp): a jittered
// circle, a zigzag, and polylines of a real corpus file.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "job/gcode_reader.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::test {

// 300 points of a circle of radius 10, each moved by up to 0.002 along
// each axis (a fixed pseudo-random sequence from `seed`).
inline std::vector<Vec2<double>> jittered_circle(std::uint32_t seed) {
  auto noise = [&] {
    seed = seed * 1664525u + 1013904223u;
    return static_cast<double>(seed >> 8) / 16777216.0 - 0.5;
  };
  std::vector<Vec2<double>> p;
  for (int k = 0; k < 300; ++k) {
    const double t = 0.02 * k;
    const double x = 10 * std::cos(t) + 0.004 * noise();
    p.push_back({x, 10 * std::sin(t) + 0.004 * noise()});
  }
  return p;
}

// 300 points, 0.3 apart along x, zigzagging by 0.05 to 0.35.
inline std::vector<Vec2<double>> zigzag() {
  std::vector<Vec2<double>> p;
  for (int k = 0; k < 300; ++k) p.push_back({0.3 * k, (k % 4 < 2 ? 0.05 : -0.05) * (1 + (k % 7))});
  return p;
}

// The first `count` G1 polylines of tball-pocket with at least 40 distinct
// points, each cut to its first 400; empty if the file cannot be read.
inline std::vector<std::vector<Vec2<double>>> tball_pocket_polylines(std::size_t count) {
  const job::GcodeFile g = job::read_gcode(std::string(KERF_TEST_DATA_DIR) + "/gcode/cncjs_tball-pocket.gcode");
  std::vector<std::vector<Vec2<double>>> out;
  for (std::size_t k = 0; g.ok && k < g.polylines.size() && out.size() < count; ++k) {
    std::vector<Vec2<double>> p;
    for (const Vec2<double>& v : g.polylines[k].points)
      if (p.empty() || !(p.back() == v)) p.push_back(v);
    if (p.size() < 40) continue;
    if (p.size() > 400) p.resize(400);
    out.push_back(p);
  }
  return out;
}

}  // namespace kerf::test
