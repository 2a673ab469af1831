// The band fitter (kerf/fit/band.hpp) on fuzzed points and widths
// (symmetric, one-sided or per vertex; now and then a tol of 0, -1, NaN or
// inf, which must be refused, or 1e-300 or 1e300, handled or refused). A line along each edge always lies
// in the band, so the fit must succeed, and the independent band referee
// (tests/support/band_checker.hpp: certified band, gates in order) must
// accept every piece. The search's start regions must admit no pair that
// the pair test refuses (bridge/start_region_check.hpp).
#include <cstddef>
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bridge/band_bridge.hpp"
#include "bridge/start_region_check.hpp"
#include "fuzz_check.hpp"
#include "fuzz_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  kerf_fuzz::FitInput f;
  const int shape = in.ConsumeIntegralInRange<int>(0, 2);
  const double right = in.ConsumeProbability<double>();  // one-sided: the right share
  kerf_fuzz::TolKind kind{};
  if (!kerf_fuzz::decode_points(in, f, &kind)) return 0;
  kerf_fuzz::dump_points(f);
  kerf_test::BandWidths w;
  if (shape == 0) {
    w = kerf_test::symmetric_widths(f.pts.size(), f.tol);
  } else if (shape == 1) {
    w = kerf_test::asymmetric_widths(f.pts.size(), f.tol * (1 - right), f.tol * right);
  } else {
    std::vector<double> tols;
    for (std::size_t k = 0; k < f.pts.size(); ++k)
      tols.push_back(f.tol * (1 + in.ConsumeIntegral<std::uint8_t>()) / 128.0);
    w = kerf_test::per_vertex_widths(tols);
  }
  if (std::getenv("KERF_FUZZ_DUMP") != nullptr) {
    for (std::size_t k = 0; k < f.pts.size(); ++k)
      std::printf("# width %zu: left %.17g right %.17g\n", k, w.left[k], w.right[k]);
    std::fflush(stdout);
  }
  kerf_test::CoreBandFitter core(f.pts, w);
  const auto r = core.fit();
  if (kind == kerf_fuzz::TolKind::bad) {
    FUZZ_CHECK(!r.ok(), "a width that is not a positive number was accepted");
    return 0;
  }
  if (kind == kerf_fuzz::TolKind::extreme) {
    // Refused cleanly, or pieces that chain and keep the points within tol.
    // The referee's gate test is not made for gates of 1e-300 (its slack
    // is 1e-9 of the scale), so the vertex verifier stands in for it.
    if (!r.ok()) return 0;
    const auto rep = kerf_test::verify(f.pts, core.pieces(r.value().pieces),
                                       std::max(f.tol, kerf_fuzz::slack_for(f.pts)));
    FUZZ_CHECK(rep.ok, rep.why.c_str());
    return 0;
  }
  FUZZ_CHECK(r.ok(), kerf::to_string(r.status()));
  {
    std::vector<kerf::Vec2<double>> p;
    std::vector<kerf::fit::BandWidth<double>> bw;
    for (std::size_t k = 0; k < f.pts.size(); ++k) {
      p.push_back({f.pts[k].x, f.pts[k].y});
      bw.push_back({w.left[k], w.right[k]});
    }
    kerf_test::StartRegionTally tally;
    FUZZ_CHECK(kerf_test::start_regions_sound(p, bw, 64, tally), tally.wrong.c_str());
  }
  kerf_fuzz::dump_pieces(core.pieces(r.value().pieces));
  const auto rep = kerf_test::check_band_fit(f.pts, w, core.pieces(r.value().pieces),
                                             kerf_fuzz::slack_for(f.pts));
  FUZZ_CHECK(rep.ok, rep.why.c_str());
  return 0;
}
