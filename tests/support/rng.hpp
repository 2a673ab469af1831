// A seeded random source for the tests: splitmix64, fully specified, so a
// seed means the same points on every target (std's distributions are not
// specified bit for bit).
#pragma once

#include <cmath>
#include <cstdint>

namespace kerf_test {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int integer(int lo, int hi) {  // [lo, hi]
    return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  double sign() { return (next() & 1) != 0 ? 1.0 : -1.0; }
  double normal() {  // Box-Muller
    const double u = 1.0 - uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2 * 3.14159265358979323846 * uniform());
  }

 private:
  std::uint64_t s_;
};

}  // namespace kerf_test
