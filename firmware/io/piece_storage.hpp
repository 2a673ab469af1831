// The pieces a fit of n points returns (at most n - 1), held on the heap for
// host programs; the fitters' own storages (fit_storage.hpp,
// band_storage.hpp) add their workspaces to it.
#pragma once

#include <vector>

#include "kerf/fit/fit.hpp"

namespace kerf::io {

class PieceStorage {
 public:
  explicit PieceStorage(std::size_t n) : pieces_(n > 1 ? n - 1 : 1) {}

  Span<fit::Piece<double>> pieces() { return {pieces_.data(), pieces_.size()}; }
  const fit::Piece<double>& piece(std::size_t k) const { return pieces_[k]; }

 private:
  std::vector<fit::Piece<double>> pieces_;
};

}  // namespace kerf::io
