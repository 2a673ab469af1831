// The fixed-point (kerf::Fixed) instantiation of the biarc fitter (the
// exact joint sets; the paper's construction is refused in fixed point).
#include "kerf/core/fixed.hpp"
#include "kerf/fit/biarc/fit_impl.hpp"

namespace kerf::fit {

template Result<Fit<Fixed>> fit_biarc_min_count(Span<const Vec2<Fixed>>, Span<const Vec2<Fixed>>,
                                                Span<const BandWidth<Fixed>>, BiarcOptions,
                                                BiarcWorkspace<Fixed>, Span<BiarcPiece<Fixed>>);
template Fixed biarc_deviation(Span<const Vec2<Fixed>>, std::uint32_t, std::uint32_t,
                               const Biarc<Fixed>&);
template void estimate_tangents(Span<const Vec2<Fixed>>, Span<Vec2<Fixed>>);

}  // namespace kerf::fit
