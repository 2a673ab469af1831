#include "cli/biarc_job.hpp"

#include <cmath>

#include "io/biarc_storage.hpp"

namespace kerf::cli {

namespace {

// The unit tangent of a segment at its start (end = false) or end.
Vec2<double> tangent_of(const Segment<double>& s, bool end) {
  if (!s.is_arc()) return fit::unit_of(s.end - s.start);
  const Vec2<double> r = (end ? s.end : s.start) - s.centre;
  return fit::unit_of(s.dir > 0 ? r.perp() : -r.perp());
}

double turn(Vec2<double> a, Vec2<double> b) { return std::atan2(std::fabs(a.cross(b)), a.dot(b)); }

double distance_to(const Segment<double>& s, Vec2<double> p) { return distance_to_segment(s, p); }

}  // namespace

bool fit_biarc_path(const std::vector<Vec2<double>>& pts, const std::vector<Vec2<double>>& given,
                    double tol, std::vector<fit::BiarcPiece<double>>& out, fit::Fit<double>& fit,
                    std::string& error, Status& status, fit::BiarcMethod method) {
  const std::size_t n = pts.size();
  const std::vector<Vec2<double>> tangents = given.empty() ? io::estimated_tangents(pts) : given;
  std::vector<fit::BandWidth<double>> widths(n, {tol, tol});
  io::BiarcStorage storage(n);
  fit::BiarcOptions opts;
  opts.method = method;
  const Result<fit::Fit<double>> r = fit::fit_biarc_min_count<double>(
      {pts.data(), n}, {tangents.data(), n}, {widths.data(), n}, opts,
      storage.workspace(), storage.pieces());
  if (!r.ok()) {
    status = r.status();
    error = r.status() == Status::infeasible
                ? "no chain of biarcs fits (tangents against the path, or a corner sharper than "
                  "the band allows)"
                : std::string("fit failed: ") + to_string(r.status());
    return false;
  }
  out.assign(storage.pieces().begin(), storage.pieces().begin() + r.value().pieces);
  fit = r.value();
  if (const std::string bad = check_biarcs(pts, tangents, tol, out); !bad.empty()) {
    status = Status::infeasible;
    error = "internal error: the fit fails its own check (" + bad + ")";
    return false;
  }
  status = Status::ok;
  return true;
}

std::string check_biarcs(const std::vector<Vec2<double>>& pts,
                         const std::vector<Vec2<double>>& tangents, double tol,
                         const std::vector<fit::BiarcPiece<double>>& pieces) {
  std::size_t at = 0;
  double scale = 0;
  for (const Vec2<double>& p : pts) scale = std::fmax(scale, std::fmax(std::fabs(p.x), std::fabs(p.y)));
  const double eps = 1e-9 * (scale + 1);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const fit::BiarcPiece<double>& b = pieces[k];
    const std::string name = "biarc " + std::to_string(k + 1);
    if (b.first != at || !(b.first < b.last) || b.last >= pts.size()) return name + ": not contiguous";
    const Segment<double>& a1 = b.arc[0];
    const Segment<double>& a2 = b.arc[1];
    if ((a1.start - pts[b.first]).norm() > eps || (a2.end - pts[b.last]).norm() > eps ||
        (a1.end - a2.start).norm() > eps)
      return name + ": ends do not meet";
    if (turn(tangent_of(a1, false), tangents[b.first]) > 1e-9) return name + ": start tangent";
    if (turn(tangent_of(a1, true), tangent_of(a2, false)) > 1e-9) return name + ": corner at the joint";
    if (turn(tangent_of(a2, true), tangents[b.last]) > 1e-9) return name + ": end tangent";
    for (std::size_t q = b.first; q <= b.last; ++q)
      if (std::fmin(distance_to(a1, pts[q]), distance_to(a2, pts[q])) > tol * (1 + 1e-9) + eps)
        return name + ": point " + std::to_string(q) + " is farther than tol";
    at = b.last;
  }
  if (at + 1 != pts.size()) return "the biarcs stop before the last point";
  return {};
}

}  // namespace kerf::cli
