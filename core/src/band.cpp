// The band fitter for each scalar type the core is built for.
#include "kerf/core/fixed.hpp"
#include "kerf/fit/band/fit_impl.hpp"
#include "scalar_types.hpp"

namespace kerf::fit {

#define KERF_BAND_INSTANCES(S)                                                                   \
  template class BandRegion<S>;                                                                  \
  template Result<Fit<S>> fit_band_min_count(Span<const Vec2<S>>, Span<const BandWidth<S>>,      \
                                             BandWorkspace<S>, Span<Piece<S>>);                  \
  template Result<Fit<S>> fit_band_min_count(Span<const Vec2<S>>, Span<const BandWidth<S>>,      \
                                             BandWorkspace<S>, Span<Piece<S>>, S);               \
  template Result<Fit<S>> fit_band_min_error(Span<const Vec2<S>>, Span<const BandWidth<S>>,      \
                                             std::uint32_t, BandWorkspace<S>, Span<Piece<S>>);   \
  template Result<std::uint32_t> count_band_min(Span<const Vec2<S>>, Span<const BandWidth<S>>,   \
                                                BandWorkspace<S>);                               \
  template Result<BandRegion<S>> band_region(Span<const Vec2<S>>, Span<const BandWidth<S>>,      \
                                             BandWorkspace<S>);                                  \
  template bool band_pair_valid(const BandRegion<S>&, std::uint32_t, std::uint32_t, Segment<S>*);

KERF_FOR_EACH_SCALAR(KERF_BAND_INSTANCES)

}  // namespace kerf::fit
