// The core on a Cortex-M4: fits the ESGI'104 parabola in static storage and
// prints the result through semihosting. The test compares it with the
// reference figures (5 pieces at tol 0.0183, max error 0.0161900). Then the
// same fit in kerf::Fixed, by the vertex and the band fitter, whose text must
// equal the host's
// (fixed_parabola.expected). KERF_MCU_FIXED_ONLY (Cortex-M0, no FPU) builds
// the fixed-point part alone.
#include <cstdio>

#include "fixed_parabola.hpp"
#include "kerf/fit/fit.hpp"

namespace {

kerf::mcu::FixedParabola fixed_state;
char fixed_text[2048];

#ifndef KERF_MCU_FIXED_ONLY
constexpr unsigned kPoints = 200;

kerf::Vec2<double> points[kPoints];
std::uint32_t words[kerf::fit::workspace_words(kPoints)];
kerf::fit::Interval<double> intervals[kerf::fit::workspace_intervals(kPoints)];
kerf::Vec2<double> scratch[kerf::fit::workspace_points(kPoints)];
kerf::fit::Piece<double> pieces[kPoints - 1];
#endif

}  // namespace

int main() {
#ifndef KERF_MCU_FIXED_ONLY
  // y = 300 - 200 (1 - x/500)^2 at x = linspace(500, 0, 200), as in the report.
  for (unsigned k = 0; k < kPoints; ++k) {
    const double x = 500.0 - 500.0 * k / (kPoints - 1);
    const double u = 1.0 - x / 500.0;
    points[k] = {x, 300.0 - 200.0 * u * u};
  }
  const kerf::fit::Workspace<double> ws{{words, sizeof words / sizeof words[0]},
                                        {intervals, sizeof intervals / sizeof intervals[0]},
                                        {scratch, kPoints}};
  const auto r = kerf::fit::fit_min_count<double>({points, kPoints}, 0.0183,
                                                  kerf::fit::Method::optimal, ws, {pieces, kPoints - 1});
  if (!r.ok()) {
    std::printf("fit failed: %s\n", kerf::to_string(r.status()));
    return 1;
  }
  std::printf("pieces %u max error %.7f\n", static_cast<unsigned>(r.value().pieces), r.value().max_error);
  for (unsigned k = 0; k < r.value().pieces; ++k)
    std::printf("%u -> %u\n", static_cast<unsigned>(pieces[k].first), static_cast<unsigned>(pieces[k].last));
#endif
  kerf::mcu::fit_fixed_parabola(fixed_state, fixed_text, sizeof fixed_text);
  std::printf("%s", fixed_text);
  return 0;
}
