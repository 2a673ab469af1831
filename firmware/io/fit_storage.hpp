// Heap-backed storage for core's fitter, for host programs (the CLI, tests,
// benchmarks). core itself never allocates: it takes these spans.
#pragma once

#include <cstdint>
#include <vector>

#include "io/piece_storage.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::io {

class FitStorage : public PieceStorage {
 public:
  explicit FitStorage(std::size_t n)
      : PieceStorage(n),
        words_(fit::workspace_words(n)),
        intervals_(fit::workspace_intervals(n)),
        points_(fit::workspace_points(n)) {}

  fit::Workspace<double> workspace() {
    return {{words_.data(), words_.size()},
            {intervals_.data(), intervals_.size()},
            {points_.data(), points_.size()}};
  }
 private:
  std::vector<std::uint32_t> words_;
  std::vector<fit::Interval<double>> intervals_;
  std::vector<Vec2<double>> points_;
};

}  // namespace kerf::io
