// The double instantiation of the fitter.
#include "kerf/fit/detail/fit_impl.hpp"

namespace kerf::fit {

template Result<Fit<double>> fit_min_count(Span<const Vec2<double>>, double, Method,
                                           Workspace<double>, Span<Piece<double>>);
template Result<Fit<double>> fit_min_count(Span<const Vec2<double>>, double, Method,
                                           Workspace<double>, Span<Piece<double>>, double);
template Result<Fit<double>> fit_min_error(Span<const Vec2<double>>, std::uint32_t, Method,
                                           Workspace<double>, Span<Piece<double>>);
template Result<std::uint32_t> count_min(Span<const Vec2<double>>, double, Method,
                                         Workspace<double>);
template Status validate_points(Span<const Vec2<double>>, std::size_t&);

}  // namespace kerf::fit
