// kerf's band fitter: the fewest arcs (lines as their limit) from input
// point to input point that stay inside a tolerance region R around the
// polyline and cross its gates in order (Drysdale, Rote, Sturm, section 2;
// R and the band it guarantees are described in fit/band/region.hpp). Unlike
// the vertex criterion (fit/fit.hpp), which watches only the points, the
// whole cut stays within the band. Everything runs in caller-provided
// storage; see BandWorkspace.
#pragma once

#include <cstdint>

#include "kerf/core/span.hpp"
#include "kerf/core/status.hpp"
#include "kerf/fit/band/region.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::fit {

// 6 n words suffice; the seventh n speeds up the tie-break.
constexpr std::size_t band_workspace_words(std::size_t n) { return 7 * n; }

template <class S>
struct BandWorkspace {
  Span<std::uint32_t> words;      // >= band_workspace_words(n)
  Span<Vec2<S>> points;           // >= n: the points scaled by a power of two
  Span<BandVertex<S>> vertices;   // >= n: the region
  Span<BandChainSlot<S>> chains{};  // optional: a cache of the region's chains (BandRegion::cache_chains)
};

// A chain cache for n points: the cells a search's layer spans, both sides;
// more is rarely used.
constexpr std::size_t band_chain_slots(std::size_t n) {
  std::size_t size = 2;
  while (size < 2 * n && size < 512) size *= 2;
  return size;
}

// Fewest pieces inside the band of `widths` (one per point, each side >= 0,
// some side > 0). Among all solutions with that count it returns one whose
// band, scaled down uniformly, is smallest (to 1e-6 relative): that is
// fit.tol (in the widths' units: the largest width times the scale).
// Piece::error is the piece's largest distance from the polyline between
// its end points; fit.max_error the largest of those.
template <class S>
Result<Fit<S>> fit_band_min_count(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                                  BandWorkspace<S> ws, Span<Piece<S>> out);

// The same count, with the tie-break's precision `tie_break` (relative, 1e-6
// above; each step of it is a whole search). tie_break >= 1 skips it: the
// pieces are then a fewest-pieces solution in the band as given.
template <class S>
Result<Fit<S>> fit_band_min_count(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                                  BandWorkspace<S> ws, Span<Piece<S>> out, S tie_break);

// The smallest uniform scale of `widths` (to 1e-9 relative) at which
// `pieces` pieces suffice, and such a solution; fit.tol is the largest
// width times that scale.
template <class S>
Result<Fit<S>> fit_band_min_error(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                                  std::uint32_t pieces, BandWorkspace<S> ws, Span<Piece<S>> out);

// Only the fewest-pieces count.
template <class S>
Result<std::uint32_t> count_band_min(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                                     BandWorkspace<S> ws);

// Builds R for the points as given (not scaled), for callers that draw or
// check it. ws.vertices receives it.
template <class S>
Result<BandRegion<S>> band_region(Span<const Vec2<S>> pts, Span<const BandWidth<S>> widths,
                                  BandWorkspace<S> ws);

// Is p_i -> p_j a valid piece in R? Writes the chosen segment if so.
template <class S>
bool band_pair_valid(const BandRegion<S>& region, std::uint32_t i, std::uint32_t j,
                     Segment<S>* chosen);

}  // namespace kerf::fit
