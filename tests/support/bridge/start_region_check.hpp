// The band search's start regions (kerf/fit/band/start_region.hpp) against
// the pair test they stand in front of: a "yes" must never be a pair that
// the pair test refuses. Walks each start the way the search asks it (j
// growing, no barrier between), both orientations. Includes core, so it is
// not part of kerf_test_support.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/band_storage.hpp"
#include "kerf/fit/band.hpp"
#include "kerf/fit/band/pair.hpp"
#include "kerf/fit/band/start_region.hpp"
#include "kerf/fit/detail/chord.hpp"

namespace kerf_test {

struct StartRegionTally {
  std::size_t valid = 0;     // pairs the pair test accepts
  std::size_t admitted = 0;  // of them, those a start region admits
  std::string wrong;         // the first pair admitted and refused, if any
};

// Adds the pairs i -> j, j - i <= span, of the band of `widths` around
// `pts` to `tally`; false (tally.wrong says which) on a wrong yes, or when
// the region cannot be built (tally.wrong says so).
inline bool start_regions_sound(const std::vector<kerf::Vec2<double>>& pts,
                                const std::vector<kerf::fit::BandWidth<double>>& widths, std::uint32_t span,
                                StartRegionTally& tally) {
  const std::size_t n = pts.size();
  kerf::io::BandStorage storage(n);
  const kerf::fit::BandWorkspace<double> ws = storage.workspace();
  const auto built = kerf::fit::band_region<double>({pts.data(), n}, {widths.data(), n}, ws);
  if (!built.ok()) {
    tally.wrong = "the region was not built";
    return false;
  }
  kerf::fit::BandRegion<double> region = built.value();
  region.cache_chains(ws.chains);
  const auto last = static_cast<std::uint32_t>(n - 1);
  for (std::uint32_t i = 0; i < last; ++i) {
    for (const int orient : {1, -1}) {
      kerf::fit::band_detail::StartRegion<double> fresh;
      fresh.reset(region, i, orient);
      for (std::uint32_t j = i + 1; j <= last && j - i <= span; ++j) {
        if (j > i + 1 && region.vertex(j - 1).barrier) break;  // the search asks no further
        if (kerf::fit::closes_on_itself(region.point(i), region.point(j))) continue;
        const bool yes = fresh.reach(region, j) && fresh.admits(region, j);
        kerf::fit::BandPair<double> pair(region, i, j, orient);
        pair.set_clear_between();
        kerf::fit::PsiRange<double> range;
        std::uint32_t fail = 0;
        const bool ok = pair.run(range, fail);
        if (yes && !ok) {
          tally.wrong = "pair " + std::to_string(i) + " -> " + std::to_string(j) + (orient > 0 ? " ccw" : " cw") +
                        ": a start region admits it, the pair test refuses it";
          return false;
        }
        tally.valid += ok ? 1 : 0;
        tally.admitted += ok && yes ? 1 : 0;
      }
    }
  }
  return true;
}

}  // namespace kerf_test
