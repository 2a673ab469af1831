#include "job/fit_fixed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/options.hpp"
#include "kerf/core/fixed_convert.hpp"
#include "kerf/fit/band.hpp"

namespace kerf::job {

double fixed_fit_slack(Span<const Vec2<double>> pts) {
  double big = 1.0;
  for (const Vec2<double>& p : pts) big = std::max({big, std::abs(p.x), std::abs(p.y)});
  return 64.0 * fixed_quantum * std::exp2(std::ceil(std::log2(big)));
}

double fixed_min_tol(Span<const Vec2<double>> pts) { return 16.0 * fixed_fit_slack(pts); }

namespace {

// The fixed-point pieces in double: their ends are the input's own points
// (as read), their centres converted.
void pieces_to_double(Span<const Vec2<double>> pts, Span<const fit::Piece<Fixed>> fixed,
                      Span<fit::Piece<double>> out) {
  const auto back = [](Vec2<Fixed> v) { return Vec2<double>{to_double(v.x), to_double(v.y)}; };
  for (std::size_t k = 0; k < fixed.size(); ++k) {
    const fit::Piece<Fixed>& f = fixed[k];
    const Segment<double> s{f.segment.kind, pts[f.first], pts[f.last], back(f.segment.centre), f.segment.dir};
    out[k] = {f.first, f.last, s, to_double(f.error)};
  }
}

}  // namespace

Result<fit::Fit<double>> fit_vertex_fixed(Span<const Vec2<double>> pts, double tol,
                                          std::uint32_t pieces, fit::Method method,
                                          Span<fit::Piece<double>> out, bool tie_break) {
  const std::size_t n = pts.size();
  std::vector<Vec2<Fixed>> p(n);
  for (std::size_t k = 0; k < n; ++k) p[k] = {fixed_from_double(pts[k].x), fixed_from_double(pts[k].y)};
  std::vector<std::uint32_t> words(fit::workspace_words(n));
  std::vector<fit::Interval<Fixed>> intervals(fit::workspace_intervals(n));
  std::vector<Vec2<Fixed>> scaled(fit::workspace_points(n));
  std::vector<fit::Piece<Fixed>> fixed_out(out.size());
  const fit::Workspace<Fixed> ws{{words.data(), words.size()},
                                 {intervals.data(), intervals.size()},
                                 {scaled.data(), scaled.size()}};
  const Span<const Vec2<Fixed>> in(p.data(), n);
  const Span<fit::Piece<Fixed>> dst(fixed_out.data(), fixed_out.size());
  const Result<fit::Fit<Fixed>> r =
      pieces > 0 ? fit::fit_min_error(in, pieces, method, ws, dst)
      : tie_break ? fit::fit_min_count(in, fixed_from_double(tol), method, ws, dst)
                  : fit::fit_min_count(in, fixed_from_double(tol), method, ws, dst, Fixed(1));
  if (!r.ok()) return r.status();
  pieces_to_double(pts, {fixed_out.data(), r.value().pieces}, out);
  // The tol asked for stays exact in the report; a found tol is converted.
  return fit::Fit<double>{r.value().pieces, to_double(r.value().max_error),
                          pieces > 0 ? to_double(r.value().tol) : tol};
}

Result<fit::Fit<double>> fit_band_fixed(Span<const Vec2<double>> pts,
                                        Span<const fit::BandWidth<double>> widths,
                                        std::uint32_t pieces, Span<fit::Piece<double>> out,
                                        bool tie_break) {
  const std::size_t n = pts.size();
  std::vector<Vec2<Fixed>> p(n);
  std::vector<fit::BandWidth<Fixed>> w(n);
  for (std::size_t k = 0; k < n; ++k) {
    p[k] = {fixed_from_double(pts[k].x), fixed_from_double(pts[k].y)};
    w[k] = {fixed_from_double(widths[k].left), fixed_from_double(widths[k].right)};
  }
  std::vector<std::uint32_t> words(fit::band_workspace_words(n));
  std::vector<Vec2<Fixed>> scaled(n);
  std::vector<fit::BandVertex<Fixed>> vertices(n);
  std::vector<fit::Piece<Fixed>> fixed_out(out.size());
  const fit::BandWorkspace<Fixed> ws{{words.data(), words.size()},
                                     {scaled.data(), scaled.size()},
                                     {vertices.data(), vertices.size()}};
  const Span<const Vec2<Fixed>> in(p.data(), n);
  const Span<const fit::BandWidth<Fixed>> win(w.data(), n);
  const Span<fit::Piece<Fixed>> dst(fixed_out.data(), fixed_out.size());
  const Result<fit::Fit<Fixed>> r = pieces > 0 ? fit::fit_band_min_error(in, win, pieces, ws, dst)
                                     : tie_break ? fit::fit_band_min_count(in, win, ws, dst)
                                                 : fit::fit_band_min_count(in, win, ws, dst, Fixed(1));
  if (!r.ok()) return r.status();
  pieces_to_double(pts, {fixed_out.data(), r.value().pieces}, out);
  // The widest width asked for stays exact in the report; a found tol is converted.
  double widest = 0.0;
  for (const fit::BandWidth<double>& b : widths) widest = std::max({widest, b.left, b.right});
  return fit::Fit<double>{r.value().pieces, to_double(r.value().max_error),
                          pieces > 0 ? to_double(r.value().tol) : widest};
}

// --numeric fixed: every coordinate inside Q31.32's range (else FILE:LINE),
// and a tol (0: none given) the grid resolves at the points' magnitude.
bool fixed_fits(const io::PointFile& in, double tol) {
  for (std::size_t k = 0; k < in.points.size(); ++k) {
    const Vec2<double> p = in.points[k];
    if (std::fabs(p.x) < kFixedLimit && std::fabs(p.y) < kFixedLimit) continue;
    std::fprintf(stderr,
                 "%s:%zu: coordinate out of the fixed-point fit's range (|x|, |y| < 2^30 = "
                 "1073741824) for --numeric fixed: \"%.17g\"\n",
                 in.file.c_str(), in.point_lines[k], std::fabs(p.x) < kFixedLimit ? p.y : p.x);
    return false;
  }
  if (tol == 0.0) return true;
  const double finest = fixed_min_tol(Span<const Vec2<double>>(in.points.data(), in.points.size()));
  char buf[200];
  if (tol >= kFixedLimit)
    std::snprintf(buf, sizeof buf, "%.6g is out of the fixed-point fit's range (< 2^30 = 1073741824)", tol);
  else if (tol < finest)
    std::snprintf(buf, sizeof buf,
                  "%.6g is finer than the fixed-point fit resolves for these points (at least "
                  "%.3g; or use --numeric double)",
                  tol, finest);
  else
    return true;
  io::usage_error(std::string("--tol: ") + buf);
  return false;
}

}  // namespace kerf::job
