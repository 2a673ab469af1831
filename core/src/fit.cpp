// The point fitter (vertex and ESGI rules) for each scalar type the core is
// built for.
#include "kerf/core/fixed.hpp"
#include "kerf/fit/detail/fit_impl.hpp"
#include "scalar_types.hpp"

namespace kerf::fit {

#define KERF_FIT_INSTANCES(S)                                                                     \
  template Result<Fit<S>> fit_min_count(Span<const Vec2<S>>, S, Method, Workspace<S>,             \
                                        Span<Piece<S>>);                                          \
  template Result<Fit<S>> fit_min_count(Span<const Vec2<S>>, S, Method, Workspace<S>,             \
                                        Span<Piece<S>>, S);                                       \
  template Result<Fit<S>> fit_min_error(Span<const Vec2<S>>, std::uint32_t, Method, Workspace<S>, \
                                        Span<Piece<S>>);                                          \
  template Result<std::uint32_t> count_min(Span<const Vec2<S>>, S, Method, Workspace<S>);         \
  template Status validate_points(Span<const Vec2<S>>, std::size_t&);

KERF_FOR_EACH_SCALAR(KERF_FIT_INSTANCES)

}  // namespace kerf::fit
