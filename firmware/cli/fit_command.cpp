#include "cli/fit_command.hpp"

#include <CLI/CLI.hpp>
#include <cctype>
#include <cerrno>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#include "cli/band_widths.hpp"
#include "cli/check_fit.hpp"
#include "cli/fit_fixed.hpp"
#include "cli/fit_job.hpp"
#include "cli/fit_write.hpp"
#include "cli/options.hpp"
#include "io/band_storage.hpp"
#include "io/fit_output.hpp"
#include "io/fit_storage.hpp"
#include "io/point_file.hpp"
#include "kerf/fit/band.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::cli {

namespace {

// "1 piece", "5 pieces".
std::string count(std::size_t n, const char* one, const char* many) {
  std::string s = std::to_string(n);
  s += ' ';
  s += n == 1 ? one : many;
  return s;
}

bool parse_method(const std::string& text, fit::Method& method) {
  if (text == "optimal") method = fit::Method::optimal;
  else if (text == "esgi-max") method = fit::Method::esgi_max;
  else if (text == "esgi-mean") method = fit::Method::esgi_mean;
  else return false;
  return true;
}


}  // namespace

CLI::App* add_fit_command(CLI::App& app, FitOptions& opts) {
  CLI::App* fit = app.add_subcommand(
      "fit", "Fit the fewest arcs within --tol of the points, or the smallest tol for --pieces K");
  fit->add_option("--tol", opts.tol, "Largest distance of a point from its piece (> 0)")
      ->type_name("EPS");
  fit->add_option("--pieces", opts.pieces,
                  "Number of pieces: find the smallest tol instead of giving --tol")
      ->type_name("K");
  fit->add_option("--tol-left", opts.tol_left,
                  "band: the band's width left of the path (>= 0; default --tol)")
      ->type_name("A");
  fit->add_option("--tol-right", opts.tol_right,
                  "band: the band's width right of the path (>= 0; default --tol)")
      ->type_name("B");
  fit->add_option("--criterion", opts.criterion,
                  "vertex (points within tol of their arc), band (the whole arc within the "
                  "tolerance band of the polyline) or biarc (the fewest tangent-continuous "
                  "biarcs within the band)")
      ->type_name("NAME")
      ->capture_default_str();
  fit->add_option("--method", opts.method, "optimal, esgi-max or esgi-mean")
      ->type_name("NAME")
      ->capture_default_str();
  fit->add_option("--format", opts.format,
                  "Output format: esgi, json, gcode (G0/G1/G2/G3, I/J relative) or svg (plot "
                  "with the band and the deviation)")
      ->type_name("NAME")
      ->capture_default_str();
  fit->add_option("--feed", opts.feed, "gcode: feed rate F in mm/min (default 1000)")
      ->type_name("F");
  fit->add_option("-o,--output", opts.output,
                  "Write to FILE (through a temp file and a rename) instead of stdout")
      ->type_name("FILE");
  fit->add_option("--tangents", opts.tangents,
                  "biarc: given (from the file's tangent columns) or estimate (circle through "
                  "each point and its neighbours); default: given when the file has them")
      ->type_name("given|estimate");
  fit->add_option("--tangent-format", opts.tangent_format,
                  "biarc: vector (x y tx ty) or angle (x y degrees)")
      ->type_name("NAME")
      ->capture_default_str();
  fit->add_option("--numeric", opts.numeric,
                  "Scalar type of the fit: double, or fixed (Q31.32, what a core without an FPU "
                  "runs; vertex and band criteria)")
      ->type_name("TYPE")
      ->capture_default_str();
  fit->add_option("--tie-break", opts.tie_break,
                  "vertex, band: among the fewest-pieces fits, smallest (default: the one at the "
                  "smallest tol) or none (the fit at --tol itself, what --stream writes)")
      ->type_name("smallest|none");
  fit->add_flag("--stream", opts.stream,
                "Read the points line by line and write each piece once it is decided, in "
                "memory fixed by --window (vertex or band criterion, one path)");
  fit->add_option("--window", opts.window, "--stream: the most points held at once (4..65536)")
      ->type_name("N");
  fit->add_option("--extent", opts.extent,
                  "--stream: the largest |x| or |y| of the input, mm (points beyond are refused); "
                  "required with --numeric fixed, which then computes what the whole-input fit does "
                  "for inputs whose largest coordinate lies in the same power-of-two octave")
      ->type_name("E");
  fit->add_option("file", opts.file, "Point file, one \"x y\" per line; - for stdin")
      ->type_name("FILE|-")
      ->required();
  return fit;
}

namespace {

// Checks the options that do not depend on the input; 0 when they are fine.
int check_options(const FitOptions& opts, bool band, fit::Method& method, std::uint32_t& pieces,
                  double& tol) {
  std::string error;
  if (!band && opts.criterion != "vertex")
    return usage_error("--criterion: unknown criterion " + quoted(opts.criterion) +
                       " (expected vertex, band or biarc)");
  if (!parse_method(opts.method, method))
    return usage_error("--method: unknown method " + quoted(opts.method) +
                       " (expected optimal, esgi-max or esgi-mean)");
  if (band && method != fit::Method::optimal)
    return usage_error("--method: " + quoted(opts.method) +
                       " is a vertex-criterion rule; --criterion band is always optimal");
  if (!band && (!opts.tol_left.empty() || !opts.tol_right.empty()))
    return usage_error("--tol-left and --tol-right need --criterion band");
  if (const std::string bad = numeric_problem(opts.numeric, opts.criterion); !bad.empty())
    return usage_error(bad);
  if (!opts.tie_break.empty() && opts.tie_break != "smallest" && opts.tie_break != "none") {
    std::string msg = "--tie-break: expected smallest or none, got ";  // += (armhf -Wrestrict)
    msg += quoted(opts.tie_break);
    return usage_error(msg);
  }
  if (opts.tie_break == "none" && !opts.pieces.empty())
    return usage_error("--tie-break none: needs --tol (--pieces finds the smallest tol)");
  if (!opts.pieces.empty()) {
    if (!opts.tol.empty()) return usage_error("--tol and --pieces cannot be used together");
    if (!parse_pieces(opts.pieces, pieces, error)) return usage_error(error);
  } else if (!band && opts.tol.empty()) {
    return usage_error("--tol: required (or give --pieces)");
  }
  if (!opts.tol.empty() && !parse_length("--tol", opts.tol, false, tol, error))
    return usage_error(error);
  double side = 0.0;
  if (!opts.tol_left.empty() && !parse_length("--tol-left", opts.tol_left, true, side, error))
    return usage_error(error);
  if (!opts.tol_right.empty() && !parse_length("--tol-right", opts.tol_right, true, side, error))
    return usage_error(error);
  return kExitOk;
}

}  // namespace

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
  usage_error(std::string("--tol: ") + buf);
  return false;
}

int run_fit(const FitOptions& opts) {
  if (opts.stream || !opts.window.empty()) return run_fit_stream(opts);
  if (!opts.extent.empty()) return usage_error("--extent needs --stream");
  if (opts.criterion == "biarc") {
    if (const std::string bad = numeric_problem(opts.numeric, opts.criterion); !bad.empty())
      return usage_error(bad);
    if (!opts.tie_break.empty()) return usage_error("--tie-break: for the vertex and band criteria");
    return run_fit_biarc(opts);
  }
  if (!opts.tangents.empty() || opts.tangent_format != "vector")
    return usage_error("--tangents and --tangent-format need --criterion biarc");
  const bool band = opts.criterion == "band";
  const bool by_pieces = !opts.pieces.empty();
  const bool tie_break = opts.tie_break != "none";
  fit::Method method{};
  std::uint32_t pieces = 0;
  double tol = 0.0;
  if (const int rc = check_options(opts, band, method, pieces, tol); rc != kExitOk) return rc;
  double feed = 1000.0;
  if (const int rc = check_output_options(opts, feed); rc != kExitOk) return rc;

  io::PointFile in;
  if (!read_job(opts.file, opts.criterion, in)) return kExitUsage;
  std::vector<fit::BandWidth<double>> widths;
  if (band) {
    std::string error;
    const WidthOptions w{opts.tol, opts.tol_left, opts.tol_right, by_pieces};
    if (!band_widths(w, in, widths, error)) return usage_error(error);
  }

  const std::size_t n = in.points.size();
  const Span<const Vec2<double>> pts(in.points.data(), n);
  if (opts.numeric == "fixed" && !fixed_fits(in, by_pieces ? 0.0 : tol)) return kExitUsage;
  // A job of several paths (blank-line separated) is fitted path by path.
  std::vector<std::size_t> begins = in.path_begin;
  if (begins.empty()) begins.push_back(0);
  if (by_pieces && begins.size() > 1)
    return usage_error("--pieces: " + in.file + " holds " + std::to_string(begins.size()) +
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
      if (opts.numeric == "fixed")
        r = fit_band_fixed(path, ws_widths, by_pieces ? pieces : 0, dst, tie_break);
      else if (by_pieces)
        r = fit::fit_band_min_error(path, ws_widths, pieces, storage.workspace(), dst);
      else
        r = tie_break ? fit::fit_band_min_count(path, ws_widths, storage.workspace(), dst)
                      : fit::fit_band_min_count(path, ws_widths, storage.workspace(), dst, 1.0);
    } else if (opts.numeric == "fixed") {
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
    const double allowance = opts.numeric == "fixed" ? fixed_fit_slack(path) : 0.0;
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
  report.criterion = band ? "band" : "vertex";
  report.method = opts.method.c_str();
  report.fit = total;
  report.pieces = fitted;
  report.zero_below = io::resolution(pts);
  report.digits = io::coordinate_digits(fitted, total.tol);
  FitToWrite w;
  w.report = &report;
  w.in = &in;
  w.piece_offset = std::move(piece_offset);
  w.feed = feed;
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

  std::string summary = "kerf: " + in.file + ": " + count(n, "point", "points") + ", " +
                        (begins.size() > 1 ? count(begins.size(), "path", "paths") + ", " : "") +
                        count(total.pieces, "piece", "pieces") + ", max error " +
                        io::format_number(total.max_error, report.zero_below);
  if (by_pieces) summary += ", tol found " + io::format_number(total.tol);
  char time[64];
  std::snprintf(time, sizeof time, ", %.3f ms", ms);
  summary += time;
  summary += note;
  if (in.duplicates_dropped > 0)
    summary += ", dropped " + count(in.duplicates_dropped, "duplicate point", "duplicate points");
  std::fprintf(stderr, "%s\n", summary.c_str());
  return kExitOk;
}

}  // namespace kerf::cli
