// The vertex fitter (kerf/fit/fit.hpp, every method) on fuzzed points and
// tolerances (now and then 0, -1, NaN, inf: refused; or 1e-300, 1e300:
// handled or refused). Distinct consecutive points always have a fit (each edge is a
// line piece), so the fit must succeed, and the independent verifier
// (tests/support/verifier.hpp) must accept it, as must `kerf fit`'s own
// last check (firmware/job/check_fit.hpp).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "bridge/fit_bridge.hpp"
#include "job/check_fit.hpp"
#include "fuzz_check.hpp"
#include "fuzz_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  kerf_fuzz::FitInput f;
  const kerf::fit::Method method = kerf_test::kMethods[in.ConsumeIntegralInRange<int>(0, 2)];
  kerf_fuzz::TolKind kind{};
  if (!kerf_fuzz::decode_points(in, f, &kind)) return 0;
  kerf_fuzz::dump_points(f);
  kerf_test::CoreFitter core(f.pts);
  const auto r = core.fit(f.tol, method);
  if (kind == kerf_fuzz::TolKind::bad) {
    FUZZ_CHECK(!r.ok(), "a tol that is not a positive number was accepted");
    return 0;
  }
  if (kind == kerf_fuzz::TolKind::extreme && !r.ok()) return 0;  // refused cleanly
  FUZZ_CHECK(r.ok(), kerf::to_string(r.status()));
  const auto pieces = core.pieces(r.value().pieces);
  kerf_fuzz::dump_pieces(pieces);
  const bool optimal = method == kerf::fit::Method::optimal;
  const auto rep = kerf_test::verify(f.pts, pieces, f.tol,
                                     optimal ? kerf_test::Reach::arc : kerf_test::Reach::circle);
  // The optimal fit measures the distance to the arc itself (Reach::arc). The
  // ESGI rules measure it to the full circle, so a path that doubles back
  // inside a piece (a turn past 90 degrees) may leave a point behind the
  // arc's start, as a line piece may: only that rule is waived for them, and
  // only when the piece holds such a turn.
  const bool waived = !optimal && !rep.ok && rep.why.find("the arc misses it") != std::string::npos &&
                      kerf_fuzz::piece_doubles_back(f.pts, pieces);
  FUZZ_CHECK(rep.ok || waived, rep.why.c_str());
  std::vector<kerf::Vec2<double>> pts;
  for (const auto& p : f.pts) pts.push_back({p.x, p.y});
  std::vector<kerf::fit::Piece<double>> fitted;
  for (std::uint32_t k = 0; k < r.value().pieces; ++k) fitted.push_back(core.piece(k));
  const std::string bad = kerf::job::check_fit({pts.data(), pts.size()},
                                               {fitted.data(), fitted.size()}, f.tol);
  // kerf's own last check refuses an arc that meets its points out of order
  // (a path winding past a turn: the vertex fitter's known gap); the
  // commands then exit 1 with nothing written, which is a clean refusal.
  const bool refused = bad.find("does not pass its points in order") != std::string::npos;
  FUZZ_CHECK(bad.empty() || refused, bad.c_str());
  return 0;
}
