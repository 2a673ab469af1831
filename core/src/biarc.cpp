// The biarc fitter for each scalar type the core is built for (the exact
// joint sets; a caller's own joint sets run in double only).
#include "kerf/core/fixed.hpp"
#include "kerf/fit/biarc/fit_impl.hpp"
#include "scalar_types.hpp"

namespace kerf::fit {

#define KERF_BIARC_INSTANCES(S)                                                                  \
  template Result<Fit<S>> fit_biarc_min_count(Span<const Vec2<S>>, Span<const Vec2<S>>,         \
                                              Span<const BandWidth<S>>, BiarcOptions,            \
                                              BiarcWorkspace<S>, Span<BiarcPiece<S>>);           \
  template S biarc_deviation(Span<const Vec2<S>>, std::uint32_t, std::uint32_t, const Biarc<S>&); \
  template void estimate_tangents(Span<const Vec2<S>>, Span<Vec2<S>>);

KERF_FOR_EACH_SCALAR(KERF_BIARC_INSTANCES)

}  // namespace kerf::fit
