// Heap-backed storage for core's fitter, for host programs (the CLI, tests,
// benchmarks). core itself never allocates: it takes these spans.
#pragma once

#include <cstdint>
#include <vector>

#include "kerf/fit/fit.hpp"

namespace kerf::io {

class FitStorage {
 public:
  explicit FitStorage(std::size_t n)
      : words_(fit::workspace_words(n)),
        intervals_(fit::workspace_intervals(n)),
        points_(fit::workspace_points(n)),
        pieces_(n > 1 ? n - 1 : 1) {}

  fit::Workspace<double> workspace() {
    return {{words_.data(), words_.size()},
            {intervals_.data(), intervals_.size()},
            {points_.data(), points_.size()}};
  }
  Span<fit::Piece<double>> pieces() { return {pieces_.data(), pieces_.size()}; }
  const fit::Piece<double>& piece(std::size_t k) const { return pieces_[k]; }

 private:
  std::vector<std::uint32_t> words_;
  std::vector<fit::Interval<double>> intervals_;
  std::vector<Vec2<double>> points_;
  std::vector<fit::Piece<double>> pieces_;
};

}  // namespace kerf::io
