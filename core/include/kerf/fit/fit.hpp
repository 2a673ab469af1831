// kerf's vertex-criterion fitter: the fewest pieces (arcs, or lines as their
// limit) that start and end on input points and pass within tol of every
// input point in between, and the smallest tol a given number of pieces can
// reach. Everything runs in caller-provided storage; see Workspace.
#pragma once

#include <cstdint>

#include "kerf/core/span.hpp"
#include "kerf/core/status.hpp"
#include "kerf/fit/detail/angle_set.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf::fit {

enum class Method : std::uint8_t {
  optimal,    // exact: any circle through the end points (fit/vertex/pair.hpp)
  esgi_max,   // the report's first best-arc rule (fit/esgi/rules.hpp)
  esgi_mean,  // the report's second best-arc rule
};

template <class S>
struct Piece {
  std::uint32_t first = 0;  // index of the start point
  std::uint32_t last = 0;   // index of the end point
  Segment<S> segment{};
  S error{};                // largest distance of an inner point to the piece (arc or segment)
};

template <class S>
struct Fit {
  std::uint32_t pieces = 0;
  S max_error{};  // over all pieces
  S tol{};        // the tol asked for, or the smallest one found for a piece budget
};

// Storage for n points: index words, two interval buffers, and a copy of the
// points scaled by a power of two (exact) so that any input magnitude fits
// the arithmetic. 5 n words suffice; the sixth n speeds up the tie-break.
constexpr std::size_t workspace_words(std::size_t n) { return 6 * n; }
constexpr std::size_t workspace_intervals(std::size_t n) { return 2 * (3 * n + 8); }
constexpr std::size_t workspace_points(std::size_t n) { return n; }

template <class S>
struct Workspace {
  Span<std::uint32_t> words;       // >= workspace_words(n)
  Span<Interval<S>> intervals;     // >= workspace_intervals(n)
  Span<Vec2<S>> points;            // >= workspace_points(n)
};

// Fewest pieces within tol. Among all solutions with that count it returns
// one whose largest error is smallest (to 1e-9 relative). Needs out.size() >=
// the piece count (n - 1 always suffices).
template <class S>
Result<Fit<S>> fit_min_count(Span<const Vec2<S>> pts, S tol, Method method, Workspace<S> ws,
                             Span<Piece<S>> out);

// The same count, with the tie-break's precision `tie_break` (relative, 1e-9
// above; each step of it is a whole search). tie_break >= 1 skips it: the
// pieces are then a fewest-pieces solution at tol itself.
template <class S>
Result<Fit<S>> fit_min_count(Span<const Vec2<S>> pts, S tol, Method method, Workspace<S> ws,
                             Span<Piece<S>> out, S tie_break);

// The smallest tol (to 1e-9 relative) at which `pieces` pieces suffice, and
// such a solution.
template <class S>
Result<Fit<S>> fit_min_error(Span<const Vec2<S>> pts, std::uint32_t pieces, Method method,
                             Workspace<S> ws, Span<Piece<S>> out);

// Only the fewest-pieces count, without the tie-break or the pieces.
template <class S>
Result<std::uint32_t> count_min(Span<const Vec2<S>> pts, S tol, Method method, Workspace<S> ws);

// Checks what every entry point requires: n >= 2, finite coordinates, no two
// consecutive points equal. Returns the index of the first offending point
// through `where` (n for a short input).
template <class S>
Status validate_points(Span<const Vec2<S>> pts, std::size_t& where);

}  // namespace kerf::fit
