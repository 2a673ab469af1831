// The double instantiation of the biarc fitter.
#include "kerf/fit/biarc/fit_impl.hpp"

namespace kerf::fit {

template Result<Fit<double>> fit_biarc_min_count(Span<const Vec2<double>>,
                                                 Span<const Vec2<double>>,
                                                 Span<const BandWidth<double>>, BiarcOptions,
                                                 BiarcWorkspace<double>,
                                                 Span<BiarcPiece<double>>);
template double biarc_deviation(Span<const Vec2<double>>, std::uint32_t, std::uint32_t,
                                const Biarc<double>&);

}  // namespace kerf::fit
