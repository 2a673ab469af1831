// Test-side glue between core's biarc fitter and the independent referee
// (tests/support/biarc_checker.hpp, biarc_twin.hpp). Includes core, so it is
// not part of kerf_test_support.
#pragma once

#include <cstdint>
#include <vector>

#include "biarc_checker.hpp"
#include "bridge/band_bridge.hpp"
#include "io/biarc_storage.hpp"
#include "kerf/fit/biarc.hpp"

namespace kerf_test {

inline VPiece to_vpiece(const kerf::Segment<double>& s, std::size_t first, std::size_t last) {
  return to_vpiece(kerf::fit::Piece<double>{static_cast<std::uint32_t>(first),
                                            static_cast<std::uint32_t>(last), s, 0.0});
}

// One biarc problem: points, tangents (given, or estimated by core when
// empty) and a symmetric tol.
class CoreBiarcFitter {
 public:
  CoreBiarcFitter(const std::vector<VPoint>& pts, const std::vector<VPoint>& tangents, double tol)
      : storage_(pts.size()) {
    for (const VPoint& p : pts) pts_.push_back({p.x, p.y});
    if (tangents.empty()) {
      tangents_ = kerf::io::estimated_tangents(pts_);
    } else {
      for (const VPoint& t : tangents) tangents_.push_back({t.x, t.y});
    }
    widths_.assign(pts.size(), {tol, tol});
  }

  kerf::Result<kerf::fit::Fit<double>> fit(kerf::fit::BiarcOptions opts = {}) {
    return kerf::fit::fit_biarc_min_count<double>(
        {pts_.data(), pts_.size()}, {tangents_.data(), tangents_.size()},
        {widths_.data(), widths_.size()}, opts, storage_.workspace(), storage_.pieces());
  }
  std::vector<VBiarc> biarcs(std::uint32_t count) {
    std::vector<VBiarc> v;
    for (std::uint32_t k = 0; k < count; ++k) {
      const kerf::fit::BiarcPiece<double>& p = storage_.pieces()[k];
      v.push_back({to_vpiece(p.arc[0], p.first, p.last), to_vpiece(p.arc[1], p.first, p.last)});
    }
    return v;
  }
  const kerf::fit::BiarcPiece<double>& piece(std::size_t k) { return storage_.pieces()[k]; }
  // After fit(): the widths of the region the fit certified (double keeps
  // the input's scale), for the referee's gate rules.
  BandWidths region_widths() const {
    BandWidths w;
    for (std::size_t k = 0; k < pts_.size(); ++k) {
      w.left.push_back(storage_.region()[k].left);
      w.right.push_back(storage_.region()[k].right);
    }
    return w;
  }
  std::vector<VPoint> tangents() const {
    std::vector<VPoint> v;
    for (const auto& t : tangents_) v.push_back({t.x, t.y});
    return v;
  }

 private:
  std::vector<kerf::Vec2<double>> pts_;
  std::vector<kerf::Vec2<double>> tangents_;
  std::vector<kerf::fit::BandWidth<double>> widths_;
  kerf::io::BiarcStorage storage_;
};

}  // namespace kerf_test
