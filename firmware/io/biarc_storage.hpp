// Heap-backed storage for core's biarc fitter, for host programs (the CLI,
// tests, benchmarks). core itself never allocates: it takes these spans.
#pragma once

#include <cstdint>
#include <vector>

#include "kerf/fit/biarc.hpp"
#include "kerf/fit/biarc/tangent.hpp"

namespace kerf::io {

template <class S>
class BasicBiarcStorage {
 public:
  explicit BasicBiarcStorage(std::size_t n)
      : words_(fit::biarc_workspace_words(n)), vertices_(n), points_(n), pieces_(n > 1 ? n - 1 : 1) {}

  fit::BiarcWorkspace<S> workspace() {
    return {{words_.data(), words_.size()},
            {vertices_.data(), vertices_.size()},
            {points_.data(), points_.size()}};
  }
  Span<fit::BiarcPiece<S>> pieces() { return {pieces_.data(), pieces_.size()}; }
  // After a fit: the region it certified (its widths narrowed where the
  // band's cells were not convex), in the scaled problem's units.
  const std::vector<fit::BandVertex<S>>& region() const { return vertices_; }

 private:
  std::vector<std::uint32_t> words_;
  std::vector<fit::BandVertex<S>> vertices_;
  std::vector<Vec2<S>> points_;
  std::vector<fit::BiarcPiece<S>> pieces_;
};
using BiarcStorage = BasicBiarcStorage<double>;

// The estimated unit tangents of pts (fit/biarc/tangent.hpp).
inline std::vector<Vec2<double>> estimated_tangents(const std::vector<Vec2<double>>& pts) {
  std::vector<Vec2<double>> t(pts.size());
  fit::estimate_tangents<double>({pts.data(), pts.size()}, {t.data(), t.size()});
  return t;
}

}  // namespace kerf::io
