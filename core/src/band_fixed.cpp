// The fixed-point (kerf::Fixed) instantiation of the band fitter.
#include "kerf/core/fixed.hpp"
#include "kerf/fit/band/fit_impl.hpp"

namespace kerf::fit {

template class BandRegion<Fixed>;
template Result<Fit<Fixed>> fit_band_min_count(Span<const Vec2<Fixed>>,
                                                Span<const BandWidth<Fixed>>,
                                                BandWorkspace<Fixed>, Span<Piece<Fixed>>);
template Result<Fit<Fixed>> fit_band_min_count(Span<const Vec2<Fixed>>,
                                                Span<const BandWidth<Fixed>>,
                                                BandWorkspace<Fixed>, Span<Piece<Fixed>>, Fixed);
template Result<Fit<Fixed>> fit_band_min_error(Span<const Vec2<Fixed>>,
                                                Span<const BandWidth<Fixed>>, std::uint32_t,
                                                BandWorkspace<Fixed>, Span<Piece<Fixed>>);
template Result<std::uint32_t> count_band_min(Span<const Vec2<Fixed>>,
                                              Span<const BandWidth<Fixed>>,
                                              BandWorkspace<Fixed>);
template Result<BandRegion<Fixed>> band_region(Span<const Vec2<Fixed>>,
                                                Span<const BandWidth<Fixed>>,
                                                BandWorkspace<Fixed>);
template bool band_pair_valid(const BandRegion<Fixed>&, std::uint32_t, std::uint32_t,
                              Segment<Fixed>*);

}  // namespace kerf::fit
