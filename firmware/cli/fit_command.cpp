#include "cli/fit_command.hpp"

#include <CLI/CLI.hpp>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "cli/check_fit.hpp"
#include "io/fit_output.hpp"
#include "io/fit_storage.hpp"
#include "io/point_file.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::cli {

namespace {

int usage_error(const std::string& message) {
  std::fprintf(stderr, "kerf: %s\n", message.c_str());
  return kExitUsage;
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// "1 piece", "5 pieces".
std::string count(std::size_t n, const char* one, const char* many) {
  std::string s = std::to_string(n);
  s += ' ';
  s += n == 1 ? one : many;
  return s;
}

// --tol: a finite number > 0.
bool parse_tol(const std::string& text, double& tol, std::string& error) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  // strtod skips leading blanks; an option value must not have them either
  const bool blank = !text.empty() && std::isspace(static_cast<unsigned char>(text[0])) != 0;
  if (text.empty() || blank || end != text.c_str() + text.size()) {
    error = "--tol: not a number: " + quoted(text);
    return false;
  }
  if (!std::isfinite(v)) {
    error = "--tol: must be finite, got " + text;
    return false;
  }
  if (!(v > 0.0)) {
    error = "--tol: must be > 0, got " + text;
    return false;
  }
  tol = v;
  return true;
}

// --pieces: a whole number >= 1.
bool parse_pieces(const std::string& text, std::uint32_t& pieces, std::string& error) {
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits) {
    error = "--pieces: must be a whole number >= 1, got " + quoted(text);
    return false;
  }
  const std::size_t nz = text.find_first_not_of('0');
  if (nz == std::string::npos) {
    error = "--pieces: must be >= 1, got " + text;
    return false;
  }
  if (text.size() - nz > 9) {  // up to 999999999, far beyond any point count
    error = "--pieces: too large, got " + text;
    return false;
  }
  pieces = static_cast<std::uint32_t>(std::strtoul(text.c_str() + nz, nullptr, 10));
  return true;
}

bool parse_method(const std::string& text, fit::Method& method) {
  if (text == "optimal") method = fit::Method::optimal;
  else if (text == "esgi-max") method = fit::Method::esgi_max;
  else if (text == "esgi-mean") method = fit::Method::esgi_mean;
  else return false;
  return true;
}

// Writes all of `text` to stdout; false (and errno) if any of it failed.
bool write_stdout(const std::string& text) {
  const std::size_t n = std::fwrite(text.data(), 1, text.size(), stdout);
  return std::fflush(stdout) == 0 && n == text.size() && std::ferror(stdout) == 0;
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
  fit->add_option("--criterion", opts.criterion, "Error criterion (only: vertex)")
      ->type_name("NAME")
      ->capture_default_str();
  fit->add_option("--method", opts.method, "optimal, esgi-max or esgi-mean")
      ->type_name("NAME")
      ->capture_default_str();
  fit->add_option("--format", opts.format, "Output format: esgi or json")
      ->type_name("NAME")
      ->capture_default_str();
  fit->add_option("file", opts.file, "Point file, one \"x y\" per line; - for stdin")
      ->type_name("FILE|-")
      ->required();
  return fit;
}

int run_fit(const FitOptions& opts) {
  std::string error;
  if (opts.criterion != "vertex")
    return usage_error("--criterion: " + quoted(opts.criterion) +
                       " is not supported (only vertex is implemented)");
  fit::Method method{};
  if (!parse_method(opts.method, method))
    return usage_error("--method: unknown method " + quoted(opts.method) +
                       " (expected optimal, esgi-max or esgi-mean)");
  if (opts.format != "esgi" && opts.format != "json")
    return usage_error("--format: unknown format " + quoted(opts.format) +
                       " (expected esgi or json)");
  const bool by_pieces = !opts.pieces.empty();
  double tol = 0.0;
  std::uint32_t pieces = 0;
  if (by_pieces) {
    if (!opts.tol.empty()) return usage_error("--tol and --pieces cannot be used together");
    if (!parse_pieces(opts.pieces, pieces, error)) return usage_error(error);
  } else {
    if (opts.tol.empty()) return usage_error("--tol: required (or give --pieces)");
    if (!parse_tol(opts.tol, tol, error)) return usage_error(error);
  }

  const io::PointFile in = io::read_points(opts.file);
  if (!in.ok) {
    std::fprintf(stderr, "%s\n", io::describe_error(in).c_str());
    return kExitUsage;
  }

  const std::size_t n = in.points.size();
  io::FitStorage storage(n);
  const fit::Workspace<double> ws = storage.workspace();
  const Span<const Vec2<double>> pts(in.points.data(), n);
  const Span<fit::Piece<double>> dst = storage.pieces();

  const auto t0 = std::chrono::steady_clock::now();
  const Result<fit::Fit<double>> r = by_pieces ? fit::fit_min_error(pts, pieces, method, ws, dst)
                                               : fit::fit_min_count(pts, tol, method, ws, dst);
  const auto t1 = std::chrono::steady_clock::now();
  if (!r.ok()) {
    std::size_t where = 0;
    if (fit::validate_points(pts, where) != Status::ok) {  // the reader should have caught it
      const std::size_t line = where < n ? in.point_lines[where] : 0;
      std::fprintf(stderr, "%s:%zu: %s\n", in.file.c_str(), line, to_string(r.status()));
      return kExitUsage;
    }
    if (by_pieces && r.status() == Status::infeasible) {
      std::fprintf(stderr, "kerf: %s: no fit with %s\n", in.file.c_str(),
                   count(pieces, "piece", "pieces").c_str());
      return kExitFailure;
    }
    std::fprintf(stderr, "kerf: %s: fit failed: %s\n", in.file.c_str(), to_string(r.status()));
    return kExitFailure;
  }
  const Span<const fit::Piece<double>> fitted(dst.data(), r.value().pieces);
  if (const std::string bad = check_fit(pts, fitted, r.value().tol); !bad.empty()) {
    std::fprintf(stderr,
                 "kerf: %s: internal error: the fit fails its own check (%s); nothing written\n",
                 in.file.c_str(), bad.c_str());
    return kExitFailure;
  }

  io::FitReport report;
  report.method = opts.method.c_str();
  report.fit = r.value();
  report.pieces = fitted;
  report.zero_below = io::resolution(pts);
  const std::string text = opts.format == "json" ? io::format_json(report) : io::format_esgi(report);
  if (!write_stdout(text)) {
    std::fprintf(stderr, "kerf: cannot write output: %s\n", std::strerror(errno));
    return kExitFailure;
  }

  const double ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  std::string summary = "kerf: " + in.file + ": " + count(n, "point", "points") + ", " +
                        count(r.value().pieces, "piece", "pieces") + ", max error " +
                        io::format_number(r.value().max_error, report.zero_below);
  if (by_pieces) summary += ", tol found " + io::format_number(r.value().tol);
  char time[64];
  std::snprintf(time, sizeof time, ", %.3f ms", ms);
  summary += time;
  if (in.duplicates_dropped > 0)
    summary += ", dropped " + count(in.duplicates_dropped, "duplicate point", "duplicate points");
  std::fprintf(stderr, "%s\n", summary.c_str());
  return kExitOk;
}

}  // namespace kerf::cli
