// The fixed-point (kerf::Fixed) instantiation of the fitter.
#include "kerf/core/fixed.hpp"
#include "kerf/fit/detail/fit_impl.hpp"

namespace kerf::fit {

template Result<Fit<Fixed>> fit_min_count(Span<const Vec2<Fixed>>, Fixed, Method,
                                           Workspace<Fixed>, Span<Piece<Fixed>>);
template Result<Fit<Fixed>> fit_min_count(Span<const Vec2<Fixed>>, Fixed, Method,
                                           Workspace<Fixed>, Span<Piece<Fixed>>, Fixed);
template Result<Fit<Fixed>> fit_min_error(Span<const Vec2<Fixed>>, std::uint32_t, Method,
                                           Workspace<Fixed>, Span<Piece<Fixed>>);
template Result<std::uint32_t> count_min(Span<const Vec2<Fixed>>, Fixed, Method,
                                         Workspace<Fixed>);
template Status validate_points(Span<const Vec2<Fixed>>, std::size_t&);

}  // namespace kerf::fit
