// The biarc fitter (kerf/fit/biarc.hpp) on fuzzed points, with the
// tangents kerf estimates, in a symmetric band (now and then of 0, -1, NaN
// or inf, which must be refused, or 1e-300 or 1e300). It may refuse (no biarc
// between two points whose tangents leave the band), but with a status, and
// what it returns must pass the independent biarc referee
// (tests/support/biarc_checker.hpp: tangent continuity, certified band,
// gate rules at the gates of the region the fit certified), and the CLI's own check (job/biarc_job.hpp: every point
// within tol of its biarc, too), whose failure a user would see as an
// internal error.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "bridge/biarc_bridge.hpp"
#include "job/biarc_job.hpp"
#include "fuzz_check.hpp"
#include "fuzz_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  kerf_fuzz::FitInput f;
  kerf_fuzz::TolKind kind{};
  if (!kerf_fuzz::decode_points(in, f, &kind)) return 0;
  kerf_fuzz::dump_points(f);
  kerf_test::CoreBiarcFitter core(f.pts, {}, f.tol);
  const auto r = core.fit();
  if (kind == kerf_fuzz::TolKind::bad)
    FUZZ_CHECK(!r.ok(), "a tol that is not a positive number was accepted");
  // At 1e-300 or 1e300 only a clean return is asked: the referee's slack
  // (1e-9 of the scale) is not made for such bands.
  if (kind == kerf_fuzz::TolKind::extreme) return 0;
  if (!r.ok()) {
    FUZZ_CHECK(r.status() != kerf::Status::ok, "a failure without a status");
    return 0;
  }
  const kerf_test::BandWidths region = core.region_widths();
  const auto rep = kerf_test::check_biarc_fit(f.pts, core.tangents(),
                                              kerf_test::symmetric_widths(f.pts.size(), f.tol),
                                              core.biarcs(r.value().pieces),
                                              kerf_fuzz::slack_for(f.pts), 1e-9, &region);
  FUZZ_CHECK(rep.ok, rep.why.c_str());
  std::vector<kerf::Vec2<double>> pts, tangents;
  for (const auto& p : f.pts) pts.push_back({p.x, p.y});
  for (const auto& t : core.tangents()) tangents.push_back({t.x, t.y});
  std::vector<kerf::fit::BiarcPiece<double>> pieces;
  for (std::uint32_t k = 0; k < r.value().pieces; ++k) pieces.push_back(core.piece(k));
  const std::string cli = kerf::job::check_biarcs(pts, tangents, f.tol, pieces, 0.0);
  FUZZ_CHECK(cli.empty(), cli.c_str());
  return 0;
}
