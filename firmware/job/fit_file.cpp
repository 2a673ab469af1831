#include "job/fit_file.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "io/band_storage.hpp"
#include "io/fit_output.hpp"
#include "io/fit_storage.hpp"
#include "io/options.hpp"
#include "io/point_file.hpp"
#include "job/biarc_job.hpp"
#include "job/band_widths.hpp"
#include "job/check_fit.hpp"
#include "job/fit_fixed.hpp"
#include "job/fit_job.hpp"
#include "job/fit_write.hpp"
#include "kerf/fit/band.hpp"

namespace kerf::job {

using io::kExitFailure;
using io::kExitOk;
using io::kExitUsage;

int fit_file(const FitOptions& opts, const FileFit& f) {
  const bool band = f.criterion == Criterion::band;
  const bool by_pieces = f.pieces > 0;
  const bool fixed = f.fixed, tie_break = f.tie_break;
  const fit::Method method = f.method;
  const std::uint32_t pieces = f.pieces;
  const double tol = f.tol;
  io::PointFile in;
  if (!read_job(opts.file, f.criterion, in)) return kExitUsage;
  std::vector<fit::BandWidth<double>> widths;
  if (band) {
    std::string error;
    const WidthOptions w{opts.tol, opts.tol_left, opts.tol_right, by_pieces};
    if (!band_widths(w, in, widths, error)) return io::usage_error(error);
  }

  const std::size_t n = in.points.size();
  const Span<const Vec2<double>> pts(in.points.data(), n);
  if (fixed && !fixed_fits(in, by_pieces ? 0.0 : tol)) return kExitUsage;
  // A job of several paths (blank-line separated) is fitted path by path.
  std::vector<std::size_t> begins = in.path_begin;
  if (begins.empty()) begins.push_back(0);
  if (by_pieces && begins.size() > 1)
    return io::usage_error("--pieces: " + in.file + " holds " + std::to_string(begins.size()) +
                           " paths; a piece budget is for one path (use --tol)");
  std::vector<fit::Piece<double>> piece_store(n - 1);
  fit::Fit<double> total{};
  std::size_t used = 0;
  std::vector<std::uint32_t> piece_offset;  // each piece's path's first point
  double ms = 0.0;
  for (std::size_t p = 0; p < begins.size(); ++p) {
    const std::size_t b = begins[p];
    const std::size_t m = (p + 1 < begins.size() ? begins[p + 1] : n) - b;
    const Span<const Vec2<double>> path(in.points.data() + b, m);
    const Span<fit::Piece<double>> dst(piece_store.data() + used, m - 1);
    const auto t0 = std::chrono::steady_clock::now();
    Result<fit::Fit<double>> r = Status::invalid_argument;
    if (band) {
      io::BandStorage storage(m);
      const Span<const fit::BandWidth<double>> ws_widths(widths.data() + b, m);
      if (fixed)
        r = fit_band_fixed(path, ws_widths, by_pieces ? pieces : 0, dst, tie_break);
      else if (by_pieces)
        r = fit::fit_band_min_error(path, ws_widths, pieces, storage.workspace(), dst);
      else
        r = tie_break ? fit::fit_band_min_count(path, ws_widths, storage.workspace(), dst)
                      : fit::fit_band_min_count(path, ws_widths, storage.workspace(), dst, 1.0);
    } else if (fixed) {
      r = fit_vertex_fixed(path, tol, by_pieces ? pieces : 0, method, dst, tie_break);
    } else {
      io::FitStorage storage(m);
      if (by_pieces)
        r = fit::fit_min_error(path, pieces, method, storage.workspace(), dst);
      else
        r = tie_break ? fit::fit_min_count(path, tol, method, storage.workspace(), dst)
                      : fit::fit_min_count(path, tol, method, storage.workspace(), dst, 1.0);
    }
    ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const std::string where = begins.size() > 1 ? " (path " + std::to_string(p + 1) + ")" : "";
    if (!r.ok()) {
      std::size_t at = 0;
      if (fit::validate_points(path, at) != Status::ok) {  // the reader should have caught it
        const std::size_t line = at < m ? in.point_lines[b + at] : 0;
        std::fprintf(stderr, "%s:%zu: %s\n", in.file.c_str(), line, to_string(r.status()));
        return kExitUsage;
      }
      if (by_pieces && r.status() == Status::infeasible) {
        std::fprintf(stderr, "kerf: %s: no fit with %s\n", in.file.c_str(),
                     count(pieces, "piece", "pieces").c_str());
        return kExitFailure;
      }
      std::fprintf(stderr, "kerf: %s%s: fit failed: %s\n", in.file.c_str(), where.c_str(), to_string(r.status()));
      return kExitFailure;
    }
    const Span<const fit::Piece<double>> fitted(dst.data(), r.value().pieces);
    // A band piece crosses each inner point's gate, so it passes within the
    // widest width of every inner point: the vertex check applies to it too.
    // Fixed-point pieces may exceed tol by the documented quantization.
    const double allowance = fixed ? fixed_fit_slack(path) : 0.0;
    if (const std::string bad = check_fit(path, fitted, r.value().tol + allowance); !bad.empty()) {
      std::fprintf(stderr,
                   "kerf: %s%s: internal error: the fit fails its own check (%s); nothing written\n",
                   in.file.c_str(), where.c_str(), bad.c_str());
      return kExitFailure;
    }
    // Inside the band, an arc is never farther from its polyline than the
    // widest width. A larger max error is a band fitter bug (fuzz_fit_band
    // found arcs at sharp turns thousands of mm out): never written.
    if (band && !(r.value().max_error <= r.value().tol * (1 + 1e-6))) {
      std::fprintf(stderr,
                   "kerf: %s%s: internal error: the fit leaves the band (max error %.9g > tol %.9g); "
                   "nothing written\n",
                   in.file.c_str(), where.c_str(), r.value().max_error, r.value().tol);
      return kExitFailure;
    }
    used += r.value().pieces;
    piece_offset.insert(piece_offset.end(), r.value().pieces, static_cast<std::uint32_t>(b));
    total.pieces += r.value().pieces;
    total.max_error = std::max(total.max_error, r.value().max_error);
    total.tol = std::max(total.tol, r.value().tol);
  }
  const Span<const fit::Piece<double>> fitted(piece_store.data(), used);

  io::FitReport report;
  report.criterion = to_string(f.criterion);
  report.method = opts.method.c_str();
  report.fit = total;
  report.pieces = fitted;
  report.zero_below = io::resolution(pts);
  report.digits = io::coordinate_digits(fitted, total.tol);
  FitToWrite w;
  w.report = &report;
  w.in = &in;
  w.piece_offset = std::move(piece_offset);
  w.feed = f.feed;
  w.tol_left = w.tol_right = total.tol;
  if (band && !by_pieces) {  // the widths as given (a shaped band: its widest)
    w.tol_left = w.tol_right = 0.0;
    for (const fit::BandWidth<double>& bw : widths) {
      w.tol_left = std::max(w.tol_left, bw.left);
      w.tol_right = std::max(w.tol_right, bw.right);
    }
  }
  std::string note;
  if (const int rc = write_fit(opts, w, note); rc != kExitOk) return rc;

  std::string what = count(total.pieces, "piece", "pieces") + ", max error " +
                     io::format_number(total.max_error, report.zero_below);
  if (by_pieces) what += ", tol found " + io::format_number(total.tol);
  print_fit_summary(in, begins.size(), what, ms, note);
  return kExitOk;
}

int fit_biarc_file(const FitOptions& opts, bool fixed, double tol, bool estimate, double feed) {
  io::PointFile in;
  if (!read_job(opts.file, Criterion::biarc, in, {true, opts.tangent_format == "angle"})) return kExitUsage;
  if (opts.tangents == "given" && in.tangents.empty())
    return io::usage_error("--tangents given: " + in.file +
                           " has no tangent columns (x y tx ty, or x y angle with --tangent-format angle)");
  if (opts.tangent_format == "angle" && in.tangents.empty())
    return io::usage_error("--tangent-format angle: " + in.file + " has no third column");
  const bool given = !estimate && !in.tangents.empty();
  if (fixed && !fixed_fits(in, tol)) return kExitUsage;

  const std::size_t n = in.points.size();
  std::vector<std::size_t> begins = in.path_begin;
  if (begins.empty()) begins.push_back(0);
  std::vector<fit::Piece<double>> arcs;  // two per biarc
  fit::Fit<double> total{};
  double ms = 0.0;
  for (std::size_t p = 0; p < begins.size(); ++p) {
    const std::size_t b = begins[p];
    const std::size_t e = p + 1 < begins.size() ? begins[p + 1] : n;
    const std::vector<Vec2<double>> pts(in.points.begin() + static_cast<long>(b),
                                        in.points.begin() + static_cast<long>(e));
    std::vector<Vec2<double>> tangents;
    if (given)
      tangents.assign(in.tangents.begin() + static_cast<long>(b),
                      in.tangents.begin() + static_cast<long>(e));
    std::vector<fit::BiarcPiece<double>> biarcs;
    fit::Fit<double> fit{};
    std::string error;
    Status status = Status::ok;
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = fit_biarc_path(pts, tangents, tol, biarcs, fit, error, status, fixed);
    ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!ok) {
      const std::string where = begins.size() > 1 ? " (path " + std::to_string(p + 1) + ")" : "";
      std::fprintf(stderr, "kerf: %s%s: %s\n", in.file.c_str(), where.c_str(), error.c_str());
      return status == Status::invalid_argument ? kExitUsage : kExitFailure;
    }
    for (const fit::BiarcPiece<double>& bi : biarcs)
      for (const Segment<double>& g : bi.arc)
        arcs.push_back({static_cast<std::uint32_t>(b + bi.first),
                        static_cast<std::uint32_t>(b + bi.last), g, bi.error});
    total.max_error = std::max(total.max_error, fit.max_error);
  }
  total.pieces = static_cast<std::uint32_t>(arcs.size());
  total.tol = tol;

  io::FitReport report;
  report.criterion = to_string(Criterion::biarc);
  report.method = opts.method.c_str();
  report.fit = total;
  report.pieces = {arcs.data(), arcs.size()};
  report.zero_below = io::resolution({in.points.data(), n});
  report.biarcs = true;
  report.digits = io::coordinate_digits(report.pieces, tol);
  FitToWrite w;  // the biarcs' first/last already index the whole job
  w.report = &report;
  w.in = &in;
  w.feed = feed;
  w.tol_left = w.tol_right = tol;
  std::string note;
  if (const int rc = write_fit(opts, w, note); rc != kExitOk) return rc;
  std::size_t lines = 0;
  for (const fit::Piece<double>& a : arcs) lines += a.segment.is_arc() ? 0 : 1;
  const std::string what = count(arcs.size() / 2, "biarc", "biarcs") + " (" +
                           count(arcs.size() - lines, "arc", "arcs") +
                           (lines > 0 ? ", " + count(lines, "line", "lines") : std::string()) +
                           "), tangents " + (given ? "given" : "estimated") + ", max error " +
                           io::format_number(total.max_error, report.zero_below);
  print_fit_summary(in, begins.size(), what, ms, note);
  return kExitOk;
}

}  // namespace kerf::job
