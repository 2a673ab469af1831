// The report's parabola fitted in kerf::Fixed, with no floating point at all,
// by the vertex and the band fitter: shared by the Cortex-M program and the
// host test, which must print the same text (tests/mcu/fixed_parabola.expected).
#pragma once

#include <cstdint>
#include <cstdio>

#include "kerf/core/fixed.hpp"
#include "kerf/fit/band.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::mcu {

inline constexpr unsigned kFixedPoints = 200;

struct FixedParabola {
  Vec2<Fixed> points[kFixedPoints];
  std::uint32_t words[fit::workspace_words(kFixedPoints)];
  fit::Interval<Fixed> intervals[fit::workspace_intervals(kFixedPoints)];
  Vec2<Fixed> scratch[fit::workspace_points(kFixedPoints)];
  fit::Piece<Fixed> pieces[kFixedPoints - 1];
  // The band fitter's storage.
  fit::BandWidth<Fixed> widths[kFixedPoints];
  std::uint32_t band_words[fit::band_workspace_words(kFixedPoints)];
  fit::BandVertex<Fixed> vertices[kFixedPoints];
};

namespace detail {

// Raw values as two 32-bit hex halves: no %lld needed from a small libc.
inline void fixed_hex(Fixed v, char* buf) {
  const auto u = static_cast<std::uint64_t>(v.raw());
  std::snprintf(buf, 20, "%08lx%08lx", static_cast<unsigned long>(u >> 32),
                static_cast<unsigned long>(u & 0xffffffffu));
}

// Appends "<what> pieces N max error E" and each piece's range and centre.
inline int print_fit(const char* what, const Result<fit::Fit<Fixed>>& r,
                     const fit::Piece<Fixed>* pieces, char* out, std::size_t size) {
  if (!r.ok()) return std::snprintf(out, size, "%s fit failed: %s\n", what, to_string(r.status()));
  char a[20], b[20];
  fixed_hex(r.value().max_error, a);
  int n = std::snprintf(out, size, "%s pieces %u max error %s\n", what,
                        static_cast<unsigned>(r.value().pieces), a);
  for (unsigned k = 0; k < r.value().pieces && n > 0 && static_cast<std::size_t>(n) < size; ++k) {
    fixed_hex(pieces[k].segment.centre.x, a);
    fixed_hex(pieces[k].segment.centre.y, b);
    n += std::snprintf(out + n, size - static_cast<std::size_t>(n), "%u -> %u centre %s %s\n",
                       static_cast<unsigned>(pieces[k].first),
                       static_cast<unsigned>(pieces[k].last), a, b);
  }
  return n;
}

}  // namespace detail

// y = 300 - 200 (1 - x/500)^2 at x = linspace(500, 0, 200), in exact ratios;
// fitted at tol 0.0183 (= 183/10000). Writes the result as text into out.
inline void fit_fixed_parabola(FixedParabola& st, char* out, std::size_t size) {
  const long last = kFixedPoints - 1;
  for (unsigned k = 0; k < kFixedPoints; ++k) {
    const Fixed u = Fixed::ratio(k, last);  // 1 - x / 500
    st.points[k] = {Fixed(500) - Fixed(500) * u, Fixed(300) - Fixed(200) * u * u};
  }
  const fit::Workspace<Fixed> ws{{st.words, sizeof st.words / sizeof st.words[0]},
                                 {st.intervals, sizeof st.intervals / sizeof st.intervals[0]},
                                 {st.scratch, kFixedPoints}};
  const Fixed tol = Fixed::ratio(183, 10000);
  const auto r = fit::fit_min_count<Fixed>({st.points, kFixedPoints}, tol, fit::Method::optimal, ws,
                                           {st.pieces, kFixedPoints - 1});
  int n = detail::print_fit("fixed", r, st.pieces, out, size);
  if (n < 0 || static_cast<std::size_t>(n) >= size) return;
  // The band fitter, the whole path inside the band of tol on both sides.
  for (unsigned k = 0; k < kFixedPoints; ++k) st.widths[k] = {tol, tol};
  const fit::BandWorkspace<Fixed> bws{{st.band_words, sizeof st.band_words / sizeof st.band_words[0]},
                                      {st.scratch, kFixedPoints},
                                      {st.vertices, kFixedPoints}};
  const auto b = fit::fit_band_min_count<Fixed>({st.points, kFixedPoints}, {st.widths, kFixedPoints},
                                                bws, {st.pieces, kFixedPoints - 1});
  detail::print_fit("fixed band", b, st.pieces, out + n, size - static_cast<std::size_t>(n));
}

}  // namespace kerf::mcu
