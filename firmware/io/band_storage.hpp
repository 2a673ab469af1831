// Heap-backed storage for core's band fitter (core itself never allocates:
// it takes these spans), for host programs: the CLI, tests, benchmarks.
#pragma once

#include <cstdint>
#include <vector>

#include "io/piece_storage.hpp"
#include "kerf/fit/band.hpp"

namespace kerf::io {

class BandStorage : public PieceStorage {
 public:
  explicit BandStorage(std::size_t n) : PieceStorage(n) { workspace_for(n); }

  fit::BandWorkspace<double> workspace() { return workspace_for(points_.size()); }

  // A workspace for n points with the sizes BandStorage(n) has, growing
  // the storage if needed: one storage serves a run of fits (kerf weld fits
  // hundreds of polylines, and zeroing a fresh chain cache, up to 330 KB,
  // for each cost more than many of their fits).
  fit::BandWorkspace<double> workspace_for(std::size_t n) {
    const std::size_t words = fit::band_workspace_words(n);
    const std::size_t slots = fit::band_chain_slots(n);
    grow(words_, words);
    grow(points_, n);
    grow(vertices_, n);
    grow(chains_, slots);
    return {{words_.data(), words}, {points_.data(), n}, {vertices_.data(), n}, {chains_.data(), slots}};
  }

 private:
  template <class T>
  static void grow(std::vector<T>& v, std::size_t size) {
    if (v.size() < size) v.resize(size);
  }

  std::vector<std::uint32_t> words_;
  std::vector<Vec2<double>> points_;
  std::vector<fit::BandVertex<double>> vertices_;
  std::vector<fit::BandChainSlot<double>> chains_;
};

}  // namespace kerf::io
