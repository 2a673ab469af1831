#include "app/fit_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "app/fit_options.hpp"
#include "io/input_file.hpp"
#include "io/options.hpp"
#include "job/fit_file.hpp"
#include "job/fit_stream.hpp"
#include "job/fit_write.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::app {

using io::kExitOk;

namespace {

bool parse_method(const std::string& text, fit::Method& method) {
  if (text == "optimal") method = fit::Method::optimal;
  else if (text == "esgi-max") method = fit::Method::esgi_max;
  else if (text == "esgi-mean") method = fit::Method::esgi_mean;
  else return false;
  return true;
}

}  // namespace

CLI::App* add_fit_command(CLI::App& app, job::FitOptions& opts) {
  CLI::App* fit = add_fitting_command(
      app, "fit", "Fit the fewest arcs within --tol of the points, or the smallest tol for --pieces K",
      opts.tol);
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
  add_numeric_option(fit, opts.numeric);
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
  add_points_file(fit, opts.file);
  return fit;
}

namespace {

// Checks the options that do not depend on the input; 0 when they are fine.
int check_options(const job::FitOptions& opts, std::optional<job::Criterion> criterion,
                  std::optional<job::Numeric> numeric, fit::Method& method, std::uint32_t& pieces, double& tol) {
  std::string error;
  const bool band = criterion == job::Criterion::band;
  if (!band && criterion != job::Criterion::vertex) return io::usage_error(job::unknown_criterion(opts.criterion));
  if (!parse_method(opts.method, method))
    return io::usage_error("--method: unknown method " + io::quoted(opts.method) +
                           " (expected optimal, esgi-max or esgi-mean)");
  if (band && method != fit::Method::optimal)
    return io::usage_error("--method: " + io::quoted(opts.method) +
                           " is a vertex-criterion rule; --criterion band is always optimal");
  if (!band && (!opts.tol_left.empty() || !opts.tol_right.empty()))
    return io::usage_error("--tol-left and --tol-right need --criterion band");
  if (!numeric) return io::usage_error(job::unknown_numeric(opts.numeric));
  if (!opts.tie_break.empty() && opts.tie_break != "smallest" && opts.tie_break != "none") {
    std::string msg = "--tie-break: expected smallest or none, got ";  // += (armhf -Wrestrict)
    msg += io::quoted(opts.tie_break);
    return io::usage_error(msg);
  }
  if (opts.tie_break == "none" && !opts.pieces.empty())
    return io::usage_error("--tie-break none: needs --tol (--pieces finds the smallest tol)");
  if (!opts.pieces.empty()) {
    if (!opts.tol.empty()) return io::usage_error("--tol and --pieces cannot be used together");
    if (!io::parse_pieces(opts.pieces, pieces, error)) return io::usage_error(error);
  } else if (!band && opts.tol.empty()) {
    return io::usage_error("--tol: required (or give --pieces)");
  }
  if (!opts.tol.empty() && !io::parse_length("--tol", opts.tol, false, tol, error))
    return io::usage_error(error);
  double side = 0.0;
  if (!opts.tol_left.empty() && !io::parse_length("--tol-left", opts.tol_left, true, side, error))
    return io::usage_error(error);
  if (!opts.tol_right.empty() && !io::parse_length("--tol-right", opts.tol_right, true, side, error))
    return io::usage_error(error);
  return kExitOk;
}

}  // namespace

int run_fit(const job::FitOptions& opts) {
  if (!io::input_readable(opts.file)) return io::kExitUsage;
  // Unknown names stay empty here; each check below refuses them in its own words.
  const std::optional<job::Criterion> criterion = job::parse_criterion(opts.criterion);
  const std::optional<job::Numeric> numeric = job::parse_numeric(opts.numeric);
  if (opts.stream || !opts.window.empty()) return job::run_fit_stream(opts, criterion, numeric);
  if (!opts.extent.empty()) return io::usage_error("--extent needs --stream");
  if (criterion == job::Criterion::biarc) {
    if (!numeric) return io::usage_error(job::unknown_numeric(opts.numeric));
    if (!opts.tie_break.empty()) return io::usage_error("--tie-break: for the vertex and band criteria");
    return run_fit_biarc(opts, *numeric);
  }
  if (!opts.tangents.empty() || opts.tangent_format != "vector")
    return io::usage_error("--tangents and --tangent-format need --criterion biarc");
  fit::Method method{};
  std::uint32_t pieces = 0;
  double tol = 0.0;
  if (const int rc = check_options(opts, criterion, numeric, method, pieces, tol); rc != kExitOk) return rc;
  double feed = 1000.0;
  if (const int rc = job::check_output_options(opts, feed); rc != kExitOk) return rc;

  job::FileFit f;
  f.criterion = *criterion;
  f.fixed = numeric == job::Numeric::fixed;
  f.method = method;
  f.pieces = pieces;
  f.tol = tol;
  f.tie_break = opts.tie_break != "none";
  f.feed = feed;
  return job::fit_file(opts, f);
}

}  // namespace kerf::app
