#include "job/biarc_job.hpp"

#include <cmath>

#include "job/fit_fixed.hpp"
#include "io/biarc_storage.hpp"
#include "kerf/core/fixed_convert.hpp"

namespace kerf::job {

namespace {

// The unit tangent of a segment at its start (end = false) or end.
Vec2<double> tangent_of(const Segment<double>& s, bool end) {
  if (!s.is_arc()) return fit::unit_of(s.end - s.start);
  const Vec2<double> r = (end ? s.end : s.start) - s.centre;
  return fit::unit_of(s.dir > 0 ? r.perp() : -r.perp());
}

double turn(Vec2<double> a, Vec2<double> b) { return std::atan2(std::fabs(a.cross(b)), a.dot(b)); }

double distance_to(const Segment<double>& s, Vec2<double> p) { return distance_to_segment(s, p); }

// The fit in kerf::Fixed; tangents (given, or empty to estimate them in
// Fixed) come back as the ones used, the pieces in double.
Result<fit::Fit<double>> fit_biarc_fixed(const std::vector<Vec2<double>>& pts,
                                         std::vector<Vec2<double>>& tangents, double tol,
                                         io::BiarcStorage& storage) {
  const std::size_t n = pts.size();
  std::vector<Vec2<Fixed>> p(n), t(n);
  for (std::size_t k = 0; k < n; ++k) p[k] = {fixed_from_double(pts[k].x), fixed_from_double(pts[k].y)};
  if (tangents.empty()) {
    fit::estimate_tangents<Fixed>({p.data(), n}, {t.data(), n});
  } else {
    for (std::size_t k = 0; k < n; ++k)
      t[k] = fit::unit_of(Vec2<Fixed>{fixed_from_double(tangents[k].x), fixed_from_double(tangents[k].y)});
  }
  const Fixed w = fixed_from_double(tol);
  const std::vector<fit::BandWidth<Fixed>> widths(n, {w, w});
  io::BasicBiarcStorage<Fixed> fs(n);
  const Result<fit::Fit<Fixed>> r = fit::fit_biarc_min_count<Fixed>(
      {p.data(), n}, {t.data(), n}, {widths.data(), n}, {}, fs.workspace(), fs.pieces());
  tangents.resize(n);
  for (std::size_t k = 0; k < n; ++k) tangents[k] = {to_double(t[k].x), to_double(t[k].y)};
  if (!r.ok()) return r.status();
  auto back = [](Vec2<Fixed> v) { return Vec2<double>{to_double(v.x), to_double(v.y)}; };
  auto segment = [&](const Segment<Fixed>& s, Vec2<double> a, Vec2<double> b) {
    return Segment<double>{s.kind, a, b, back(s.centre), s.dir};
  };
  for (std::uint32_t k = 0; k < r.value().pieces; ++k) {
    const fit::BiarcPiece<Fixed>& f = fs.pieces()[k];
    fit::BiarcPiece<double>& d = storage.pieces()[k];
    d.first = f.first;
    d.last = f.last;
    d.joint = back(f.joint);
    // The ends are the input points themselves, as in double.
    d.arc[0] = segment(f.arc[0], pts[f.first], d.joint);
    d.arc[1] = segment(f.arc[1], d.joint, pts[f.last]);
    for (int q = 0; q < 3; ++q) d.tangent[q] = back(f.tangent[q]);
    d.error = to_double(f.error);
  }
  return fit::Fit<double>{r.value().pieces, to_double(r.value().max_error), tol};
}

}  // namespace

bool fit_biarc_path(const std::vector<Vec2<double>>& pts, const std::vector<Vec2<double>>& given,
                    double tol, std::vector<fit::BiarcPiece<double>>& out, fit::Fit<double>& fit,
                    std::string& error, Status& status, bool fixed) {
  const std::size_t n = pts.size();
  std::vector<Vec2<double>> tangents = given.empty() && !fixed ? io::estimated_tangents(pts) : given;
  std::vector<fit::BandWidth<double>> widths(n, {tol, tol});
  io::BiarcStorage storage(n);
  fit::BiarcOptions opts;
  const Result<fit::Fit<double>> r =
      fixed ? fit_biarc_fixed(pts, tangents, tol, storage)
            : fit::fit_biarc_min_count<double>({pts.data(), n}, {tangents.data(), n}, {widths.data(), n},
                                               opts, storage.workspace(), storage.pieces());
  if (!r.ok()) {
    status = r.status();
    // An estimated tangent is zero only where the path turns straight back
    // between two equal steps: core refuses it as a bad argument.
    for (std::size_t k = 0; k < n && given.empty(); ++k) {
      if (tangents[k].x != 0.0 || tangents[k].y != 0.0) continue;
      error = "point " + std::to_string(k + 1) +
              ": the path turns straight back there (180 degrees between equal steps), so it "
              "has no tangent to estimate";
      return false;
    }
    error = r.status() == Status::infeasible
                ? "no chain of biarcs fits (tangents against the path, or a corner sharper than "
                  "the band allows)"
                : std::string("fit failed: ") + to_string(r.status());
    return false;
  }
  out.assign(storage.pieces().begin(), storage.pieces().begin() + r.value().pieces);
  fit = r.value();
  const double slack = fixed ? fixed_fit_slack({pts.data(), n}) : 0.0;
  if (const std::string bad = check_biarcs(pts, tangents, tol, out, slack); !bad.empty()) {
    status = Status::infeasible;
    error = "internal error: the fit fails its own check (" + bad + ")";
    return false;
  }
  status = Status::ok;
  return true;
}

std::string check_biarcs(const std::vector<Vec2<double>>& pts,
                         const std::vector<Vec2<double>>& tangents, double tol,
                         const std::vector<fit::BiarcPiece<double>>& pieces, double slack) {
  std::size_t at = 0;
  double scale = 0;
  for (const Vec2<double>& p : pts) scale = std::fmax(scale, std::fmax(std::fabs(p.x), std::fabs(p.y)));
  const double eps = 1e-9 * (scale + 1) + slack;
  // The angle allowed at an arc's end: 1e-9 rad, plus 2 slack over its chord.
  auto grid_turn = [&](const Segment<double>& s) {
    const double c = (s.end - s.start).norm();
    return slack > 0 && c > 0 ? 2 * slack / c : 0.0;
  };
  auto turn_max = [&](const Segment<double>& s) { return 1e-9 + grid_turn(s); };
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const fit::BiarcPiece<double>& b = pieces[k];
    const std::string name = "biarc " + std::to_string(k + 1);
    if (b.first != at || !(b.first < b.last) || b.last >= pts.size()) return name + ": not contiguous";
    const Segment<double>& a1 = b.arc[0];
    const Segment<double>& a2 = b.arc[1];
    if ((a1.start - pts[b.first]).norm() > eps || (a2.end - pts[b.last]).norm() > eps ||
        (a1.end - a2.start).norm() > eps)
      return name + ": ends do not meet";
    // A joint on p_first or p_last (one circle has both tangents) leaves one
    // part a point, without a tangent: the other part must meet both.
    const bool point1 = (a1.end - a1.start).norm() <= eps;
    const bool point2 = (a2.end - a2.start).norm() <= eps;
    if (point1 && point2) return name + ": both parts are points";
    const Segment<double>& head = point1 ? a2 : a1;
    const Segment<double>& tail = point2 ? a1 : a2;
    if (turn(tangent_of(head, false), tangents[b.first]) > turn_max(head)) return name + ": start tangent";
    if (!point1 && !point2 && turn(tangent_of(a1, true), tangent_of(a2, false)) > turn_max(a1) + turn_max(a2))
      return name + ": corner at the joint";
    // The second part starts with the first's end tangent, reflected in the
    // first's chord on the grid: a short first part's error carries to the end.
    const double carried = point1 || point2 ? 0.0 : grid_turn(a1);
    if (turn(tangent_of(tail, true), tangents[b.last]) > turn_max(tail) + carried)
      return name + ": end tangent";
    for (std::size_t q = b.first; q <= b.last; ++q)
      if (std::fmin(distance_to(a1, pts[q]), distance_to(a2, pts[q])) > tol * (1 + 1e-9) + eps)
        return name + ": point " + std::to_string(q) + " is farther than tol";
    at = b.last;
  }
  if (at + 1 != pts.size()) return "the biarcs stop before the last point";
  return {};
}

}  // namespace kerf::job
