// The double instantiation of the band fitter.
#include "kerf/fit/band/fit_impl.hpp"

namespace kerf::fit {

template class BandRegion<double>;
template Result<Fit<double>> fit_band_min_count(Span<const Vec2<double>>,
                                                Span<const BandWidth<double>>,
                                                BandWorkspace<double>, Span<Piece<double>>);
template Result<Fit<double>> fit_band_min_count(Span<const Vec2<double>>,
                                                Span<const BandWidth<double>>,
                                                BandWorkspace<double>, Span<Piece<double>>,
                                                double);
template Result<Fit<double>> fit_band_min_error(Span<const Vec2<double>>,
                                                Span<const BandWidth<double>>, std::uint32_t,
                                                BandWorkspace<double>, Span<Piece<double>>);
template Result<std::uint32_t> count_band_min(Span<const Vec2<double>>,
                                              Span<const BandWidth<double>>,
                                              BandWorkspace<double>);
template Result<BandRegion<double>> band_region(Span<const Vec2<double>>,
                                                Span<const BandWidth<double>>,
                                                BandWorkspace<double>);
template bool band_pair_valid(const BandRegion<double>&, std::uint32_t, std::uint32_t,
                              Segment<double>*);

}  // namespace kerf::fit
