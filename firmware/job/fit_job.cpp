#include "job/fit_job.hpp"

#include "job/biarc_job.hpp"
#include "job/check_fit.hpp"
#include "job/fit_fixed.hpp"

#include <atomic>
#include <cstdio>
#include <type_traits>
#include <utility>
#include <vector>
#include "io/band_storage.hpp"
#include "job/gcode_reader.hpp"
#include "io/fit_storage.hpp"
#include "kerf/fit/band.hpp"

namespace kerf::job {

bool read_job(const std::string& file, Criterion criterion, io::PointFile& out,
              const JobColumns& columns) {
  if (is_gcode_path(file)) {  // a G-code job: its cut paths, arcs sampled
    std::string error;
    if (read_gcode_job(file, out, error)) return true;
    std::fprintf(stderr, "%s\n", error.c_str());
    return false;
  }
  out = io::read_points(file, columns.angles);
  if (out.ok && !out.tols.empty() && criterion != Criterion::band) {
    out.line = out.point_lines.empty() ? 0 : out.point_lines[0];
    out.reason = "a third column (per-point tol) needs --criterion band";
    out.ok = false;
  }
  if (out.ok && !out.tangents.empty() && (criterion != Criterion::biarc || !columns.tangents)) {
    out.line = out.point_lines.empty() ? 0 : out.point_lines[0];
    out.reason = criterion != Criterion::biarc
                     ? "tangent columns (x y tx ty) need --criterion biarc"
                     : "tangent columns are read by kerf fit only (this command estimates them)";
    out.ok = false;
  }
  if (!out.ok) std::fprintf(stderr, "%s\n", io::describe_error(out).c_str());
  return out.ok;
}

namespace {

bool fit_once(const std::vector<Vec2<double>>& pts, const std::vector<double>& tols, double tol,
              Criterion criterion, std::vector<fit::Piece<double>>& out,
              std::string& error, Status& status, Numeric numeric, double tie_break) {
  status = Status::invalid_argument;
  const bool fixed = numeric == Numeric::fixed;
  if (criterion == Criterion::biarc) {
    if (!tols.empty()) {
      error = "a third column (per-point tol) needs --criterion band";
      return false;
    }
    std::vector<fit::BiarcPiece<double>> biarcs;
    fit::Fit<double> fit{};
    if (!fit_biarc_path(pts, {}, tol, biarcs, fit, error, status, fixed))
      return false;
    // Each biarc runs as its two arcs; both keep the biarc's point range.
    out.clear();
    for (const fit::BiarcPiece<double>& b : biarcs)
      for (const Segment<double>& g : b.arc) out.push_back({b.first, b.last, g, b.error});
    return true;
  }
  const bool band = criterion == Criterion::band;
  if (!band && !tols.empty()) {
    error = "a third column (per-point tol) needs --criterion band";
    return false;
  }
  const std::size_t n = pts.size();
  const Span<const Vec2<double>> points(pts.data(), n);
  std::vector<fit::Piece<double>> pieces(n > 1 ? n - 1 : 1);
  const Span<fit::Piece<double>> dst(pieces.data(), pieces.size());
  Result<fit::Fit<double>> r = Status::invalid_argument;
  if (band) {
    std::vector<fit::BandWidth<double>> widths(n, {tol, tol});
    for (std::size_t k = 0; k < tols.size() && k < n; ++k) widths[k] = {tols[k], tols[k]};
    const Span<const fit::BandWidth<double>> w(widths.data(), n);
    // Kept across calls: a weld fits one polyline after another.
    thread_local io::BandStorage storage(0);
    r = fixed           ? fit_band_fixed(points, w, 0, dst)
        : tie_break > 0 ? fit::fit_band_min_count(points, w, storage.workspace_for(n), dst, tie_break)
                        : fit::fit_band_min_count(points, w, storage.workspace_for(n), dst);
  } else if (fixed) {
    r = fit_vertex_fixed(points, tol, 0, fit::Method::optimal, dst);
  } else {
    io::FitStorage storage(n);
    r = tie_break > 0 ? fit::fit_min_count(points, tol, fit::Method::optimal, storage.workspace(), dst, tie_break)
                      : fit::fit_min_count(points, tol, fit::Method::optimal, storage.workspace(), dst);
  }
  if (!r.ok()) {
    status = r.status();
    error = std::string("fit failed: ") + to_string(r.status());
    return false;
  }
  // A band piece crosses each inner point's gate, so it passes within the
  // widest width (the band fit's tol) of every inner point: the vertex check
  // applies to it too. Fixed-point pieces may exceed it by the quantization.
  const Span<const fit::Piece<double>> fitted(dst.data(), r.value().pieces);
  const double allowance = fixed ? fixed_fit_slack(points) : 0.0;
  if (const std::string bad = check_fit(points, fitted, r.value().tol + allowance); !bad.empty()) {
    status = Status::infeasible;
    error = "internal error: the fit fails its own check (" + bad + ")";
    return false;
  }
  // Inside the band an arc is within the widest width of its polyline; more
  // is a band fitter bug (found by fuzz_fit_band at sharp turns).
  if (band && !(r.value().max_error <= r.value().tol * (1 + 1e-6))) {
    status = Status::infeasible;
    error = "internal error: the fit leaves the band (max error " + std::to_string(r.value().max_error) +
            " > tol " + std::to_string(r.value().tol) + ")";
    return false;
  }
  out.assign(fitted.begin(), fitted.end());
  status = Status::ok;
  return true;
}

std::atomic<std::size_t> splits{0};

// A fit that fails its own check (a fitter bug: the band fitters' known
// blind spot is a path that goes round the same circle twice, which passes
// every point's band with one arc; counted by fit_job_splits) is fitted again as two halves that share the middle point. Each half is
// within tol, so the whole is; only the piece count may exceed the minimum,
// and only where the one-piece answer was wrong. A correct program is never
// refused for it.
bool fit_split(const std::vector<Vec2<double>>& pts, const std::vector<double>& tols, double tol,
               Criterion criterion, std::vector<fit::Piece<double>>& out, std::string& error,
               Status& status, Numeric numeric, double tie_break, int depth, bool* split) {
  if (fit_once(pts, tols, tol, criterion, out, error, status, numeric, tie_break)) return true;
  const bool own_check = error.rfind("internal error:", 0) == 0;
  if (!own_check || depth >= 24 || pts.size() < 4 || (!tols.empty() && tols.size() != pts.size())) return false;
  if (split != nullptr) *split = true;
  splits.fetch_add(1, std::memory_order_relaxed);
  const std::size_t m = pts.size() / 2;
  const auto half = [&](std::size_t from, std::size_t to, auto& v) {
    return std::vector<std::decay_t<decltype(v[0])>>(v.begin() + static_cast<std::ptrdiff_t>(from),
                                                    v.begin() + static_cast<std::ptrdiff_t>(to));
  };
  const std::vector<Vec2<double>> a = half(0, m + 1, pts), b = half(m, pts.size(), pts);
  const std::vector<double> ta = tols.empty() ? tols : half(0, m + 1, tols);
  const std::vector<double> tb = tols.empty() ? tols : half(m, tols.size(), tols);
  std::vector<fit::Piece<double>> first, second;
  if (!fit_split(a, ta, tol, criterion, first, error, status, numeric, tie_break, depth + 1, split) ||
      !fit_split(b, tb, tol, criterion, second, error, status, numeric, tie_break, depth + 1, split))
    return false;
  out = std::move(first);
  for (fit::Piece<double> p : second) {
    p.first += static_cast<std::uint32_t>(m);
    p.last += static_cast<std::uint32_t>(m);
    out.push_back(p);
  }
  return true;
}

}  // namespace

std::size_t fit_job_splits() { return splits.load(std::memory_order_relaxed); }

bool fit_job(const std::vector<Vec2<double>>& pts, const std::vector<double>& tols, double tol,
             Criterion criterion, std::vector<fit::Piece<double>>& out,
             std::string& error, Status& status, Numeric numeric, double tie_break, bool* split) {
  if (split != nullptr) *split = false;
  return fit_split(pts, tols, tol, criterion, out, error, status, numeric, tie_break, 0, split);
}

}  // namespace kerf::job
