// Heap-backed storage for core's biarc fitter, for host programs (the CLI,
// tests, benchmarks). core itself never allocates: it takes these spans.
#pragma once

#include <cstdint>
#include <vector>

#include "kerf/fit/biarc_fit.hpp"
#include "kerf/fit/tangent.hpp"

namespace kerf::io {

class BiarcStorage {
 public:
  explicit BiarcStorage(std::size_t n)
      : words_(fit::biarc_workspace_words(n)), vertices_(n), pieces_(n > 1 ? n - 1 : 1) {}

  fit::BiarcWorkspace<double> workspace() {
    return {{words_.data(), words_.size()}, {vertices_.data(), vertices_.size()}};
  }
  Span<fit::BiarcPiece<double>> pieces() { return {pieces_.data(), pieces_.size()}; }

 private:
  std::vector<std::uint32_t> words_;
  std::vector<fit::BandVertex<double>> vertices_;
  std::vector<fit::BiarcPiece<double>> pieces_;
};

// The estimated unit tangents of pts (fit/tangent.hpp).
inline std::vector<Vec2<double>> estimated_tangents(const std::vector<Vec2<double>>& pts) {
  std::vector<Vec2<double>> t(pts.size());
  fit::estimate_tangents<double>({pts.data(), pts.size()}, {t.data(), t.size()});
  return t;
}

}  // namespace kerf::io
