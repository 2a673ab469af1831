// Test-side glue between core's fitter and the independent checks: converts
// points and pieces, and owns a fit's storage. This header includes core, so
// it is NOT part of kerf_test_support (whose sources see no core header);
// only test executables that link kerf_core include it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/fit_storage.hpp"
#include "kerf/fit/fit.hpp"
#include "verifier.hpp"

namespace kerf_test {

using CoreVec = kerf::Vec2<double>;
using kerf::fit::Method;

inline const Method kMethods[] = {Method::optimal, Method::esgi_max, Method::esgi_mean};

inline const char* method_name(Method m) {
  switch (m) {
    case Method::optimal: return "optimal";
    case Method::esgi_max: return "esgi_max";
    case Method::esgi_mean: return "esgi_mean";
  }
  return "?";
}

inline VPiece to_vpiece(const kerf::fit::Piece<double>& p) {
  VPiece v;
  v.arc = p.segment.is_arc();
  v.first = p.first;
  v.last = p.last;
  v.sx = p.segment.start.x;
  v.sy = p.segment.start.y;
  v.ex = p.segment.end.x;
  v.ey = p.segment.end.y;
  v.cx = p.segment.centre.x;
  v.cy = p.segment.centre.y;
  v.dir = p.segment.dir;
  return v;
}

// One fit's storage and the calls the tests make, on test-side point lists.
class CoreFitter {
 public:
  explicit CoreFitter(const std::vector<VPoint>& pts)
      : storage_(pts.size()) {
    for (const VPoint& p : pts) pts_.push_back({p.x, p.y});
  }

  kerf::Result<std::uint32_t> count(double tol, Method m) {
    return kerf::fit::count_min<double>(span(), tol, m, ws());
  }
  kerf::Result<kerf::fit::Fit<double>> fit(double tol, Method m) {
    return kerf::fit::fit_min_count<double>(span(), tol, m, ws(), storage_.pieces());
  }
  kerf::Result<kerf::fit::Fit<double>> budget(std::uint32_t pieces, Method m) {
    return kerf::fit::fit_min_error<double>(span(), pieces, m, ws(), storage_.pieces());
  }
  // The first `count` pieces of the last fit, as the verifier's pieces.
  std::vector<VPiece> pieces(std::uint32_t count) const {
    std::vector<VPiece> v;
    for (std::uint32_t k = 0; k < count && k + 1 < pts_.size(); ++k)
      v.push_back(to_vpiece(storage_.piece(k)));
    return v;
  }
  const kerf::fit::Piece<double>& piece(std::size_t k) const { return storage_.piece(k); }

 private:
  kerf::Span<const CoreVec> span() const { return {pts_.data(), pts_.size()}; }
  kerf::fit::Workspace<double> ws() { return storage_.workspace(); }
  std::vector<CoreVec> pts_;
  kerf::io::FitStorage storage_;
};

}  // namespace kerf_test
