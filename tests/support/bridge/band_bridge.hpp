// Test-side glue between core's band fitter and the independent referee
// (tests/support/band_checker.hpp, band_twin.hpp): converts widths, pieces
// and core's region R. Includes core, so it is not part of kerf_test_support.
#pragma once

#include <cstdint>
#include <vector>

#include "band_checker.hpp"
#include "band_twin.hpp"
#include "bridge/fit_bridge.hpp"
#include "io/band_storage.hpp"
#include "kerf/fit/band.hpp"

namespace kerf_test {

inline VPoint to_vpoint(kerf::Vec2<double> p) { return {p.x, p.y}; }

// One band problem (points and widths) and the calls the tests make on it.
class CoreBandFitter {
 public:
  CoreBandFitter(const std::vector<VPoint>& pts, const BandWidths& w) : storage_(pts.size()) {
    for (const VPoint& p : pts) pts_.push_back({p.x, p.y});
    for (std::size_t k = 0; k < pts.size(); ++k) widths_.push_back({w.left[k], w.right[k]});
  }

  kerf::Result<std::uint32_t> count() {
    return kerf::fit::count_band_min<double>(span(), widths(), storage_.workspace());
  }
  kerf::Result<kerf::fit::Fit<double>> fit() {
    return kerf::fit::fit_band_min_count<double>(span(), widths(), storage_.workspace(),
                                                 storage_.pieces());
  }
  // The same with the tie-break's precision (kerf weld's coarse 0.1).
  kerf::Result<kerf::fit::Fit<double>> fit(double tie_break) {
    return kerf::fit::fit_band_min_count<double>(span(), widths(), storage_.workspace(),
                                                 storage_.pieces(), tie_break);
  }
  kerf::Result<kerf::fit::Fit<double>> budget(std::uint32_t pieces) {
    return kerf::fit::fit_band_min_error<double>(span(), widths(), pieces, storage_.workspace(),
                                                 storage_.pieces());
  }
  std::vector<VPiece> pieces(std::uint32_t count) {
    std::vector<VPiece> v;
    for (std::uint32_t k = 0; k < count; ++k) v.push_back(to_vpiece(storage_.pieces()[k]));
    return v;
  }
  const kerf::fit::Piece<double>& piece(std::size_t k) { return storage_.pieces()[k]; }

  // Core's region R for these widths, in the referee's terms.
  BandRegion region() {
    // Its own storage: the fits reuse (and overwrite) the workspace's.
    region_vertices_.assign(pts_.size(), {});
    region_words_.assign(kerf::fit::band_workspace_words(pts_.size()), 0);
    region_points_.assign(pts_.size(), {});
    const kerf::fit::BandWorkspace<double> ws{{region_words_.data(), region_words_.size()},
                                              {region_points_.data(), region_points_.size()},
                                              {region_vertices_.data(), region_vertices_.size()}};
    const auto r = kerf::fit::band_region<double>(span(), widths(), ws);
    BandRegion out;
    if (!r.ok()) return out;
    region_ = r.value();
    out.pts.resize(pts_.size());
    for (std::size_t k = 0; k < pts_.size(); ++k) {
      out.pts[k] = to_vpoint(pts_[k]);
      out.gate_left.push_back(to_vpoint(region_.gate_end(static_cast<std::uint32_t>(k), 1)));
      out.gate_right.push_back(to_vpoint(region_.gate_end(static_cast<std::uint32_t>(k), -1)));
    }
    for (std::uint32_t k = 0; k + 1 < pts_.size(); ++k) {
      kerf::fit::BandChain<double> c;
      for (int side : {1, -1}) {
        region_.chain(k, side, c);
        std::vector<VPoint> chain;
        for (int t = 0; t < c.size; ++t) chain.push_back(to_vpoint(c.pt[t]));
        (side > 0 ? out.chain_left : out.chain_right).push_back(chain);
      }
    }
    return out;
  }
  // Core's verdict on one pair of the last region() (call region() first).
  bool pair_valid(std::uint32_t i, std::uint32_t j, VPiece* chosen = nullptr) const {
    kerf::Segment<double> seg;
    if (!kerf::fit::band_pair_valid(region_, i, j, &seg)) return false;
    if (chosen != nullptr) {
      kerf::fit::Piece<double> p{i, j, seg, 0.0};
      *chosen = to_vpiece(p);
    }
    return true;
  }

 private:
  kerf::Span<const kerf::Vec2<double>> span() const { return {pts_.data(), pts_.size()}; }
  kerf::Span<const kerf::fit::BandWidth<double>> widths() const {
    return {widths_.data(), widths_.size()};
  }
  std::vector<kerf::Vec2<double>> pts_;
  std::vector<kerf::fit::BandWidth<double>> widths_;
  kerf::io::BandStorage storage_;
  std::vector<kerf::fit::BandVertex<double>> region_vertices_;
  std::vector<std::uint32_t> region_words_;
  std::vector<kerf::Vec2<double>> region_points_;
  kerf::fit::BandRegion<double> region_;
};

}  // namespace kerf_test
