// A brute-force twin of kerf's biarc fitter over a GIVEN region R (the band
// twin's BandRegion, exported from core by the test bridge). No code shared
// with core/: the joint circle is built with plain trigonometry (its tangent
// at p_i makes the angle (phi_i - phi_j) / 2 with the chord), `samples`
// joints are spread evenly over it (by angle about its centre; along the
// line by x -> tan(pi (x - 1/2)) when J is a line), and a biarc is valid when
//  - its tangents cross gates i and j forwards and no gate of zero length
//    (a cusp) lies strictly between;
//  - neither arc meets a chain of cells i..j-1 or the gates i and j, except
//    the first arc at p_i and the second at p_j (1e-9 of the scale);
//  - it passes check_biarc (tangents, joint, the certified band, the gates).
// The fewest biarcs come from a dense DP over all pairs. For n <= ~30.
#pragma once

#include <cstddef>
#include <vector>

#include "band_twin.hpp"
#include "biarc_checker.hpp"

namespace kerf_test {

struct BiarcTwin {
  const BandRegion& region;
  const std::vector<VPoint>& tangents;
  const BandWidths& widths;
  int samples = 720;

  // Some valid biarc p_i -> p_j, or false.
  bool pair_valid(std::size_t i, std::size_t j, VBiarc* out = nullptr) const;
  // The fewest biarcs from p_0 to p_{n-1}, or -1.
  int min_biarcs(std::vector<VBiarc>* out = nullptr) const;
};

}  // namespace kerf_test
