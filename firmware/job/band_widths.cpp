#include "job/band_widths.hpp"

#include <algorithm>
#include <cmath>

#include "io/options.hpp"

namespace kerf::job {

bool band_widths(const WidthOptions& opts, const io::PointFile& in,
                 std::vector<fit::BandWidth<double>>& out, std::string& error) {
  const std::size_t n = in.points.size();
  const bool given = !opts.tol.empty() || !opts.left.empty() || !opts.right.empty();
  if (!in.tols.empty()) {
    if (given) {
      error = in.file + ": has a per-point tol column; --tol, --tol-left and --tol-right "
              "cannot be given too";
      return false;
    }
    out.resize(n);
    for (std::size_t k = 0; k < n; ++k) out[k] = {in.tols[k], in.tols[k]};
    return true;
  }
  // The shape for --pieces when nothing else is given: the points' extent, so
  // that scale 1 is a loose band whatever the units.
  double lo_x = in.points[0].x, hi_x = lo_x, lo_y = in.points[0].y, hi_y = lo_y;
  for (const Vec2<double>& p : in.points) {
    lo_x = std::min(lo_x, p.x);
    hi_x = std::max(hi_x, p.x);
    lo_y = std::min(lo_y, p.y);
    hi_y = std::max(hi_y, p.y);
  }
  double base = std::hypot(hi_x - lo_x, hi_y - lo_y);
  if (!opts.tol.empty() && !io::parse_length("--tol", opts.tol, false, base, error)) return false;
  if (opts.tol.empty() && !opts.by_pieces && (opts.left.empty() || opts.right.empty())) {
    error = opts.left.empty() && opts.right.empty()
                ? "--tol: required (or give --tol-left and --tol-right, or --pieces)"
                : "--tol: required with only one of --tol-left and --tol-right";
    return false;
  }
  double left = base;
  double right = base;
  if (!opts.left.empty() && !io::parse_length("--tol-left", opts.left, true, left, error)) return false;
  if (!opts.right.empty() && !io::parse_length("--tol-right", opts.right, true, right, error))
    return false;
  if (!(left + right > 0.0)) {
    error = "--tol-left and --tol-right cannot both be 0";
    return false;
  }
  out.assign(n, fit::BandWidth<double>{left, right});
  return true;
}

}  // namespace kerf::job
