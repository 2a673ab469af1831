#include "job/fit_write.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "io/options.hpp"
#include "io/fit_gcode.hpp"
#include "io/fit_svg.hpp"
#include "io/output_file.hpp"

namespace kerf::job {

using io::kExitFailure;
using io::kExitOk;

std::string count(std::size_t n, const char* one, const char* many) {
  std::string s = std::to_string(n);
  s += ' ';
  s += n == 1 ? one : many;
  return s;
}

void print_fit_summary(const io::PointFile& in, std::size_t paths, const std::string& what, double ms,
                       const std::string& note) {
  std::string summary = "kerf: " + in.file + ": " + count(in.points.size(), "point", "points") + ", " +
                        (paths > 1 ? count(paths, "path", "paths") + ", " : "") + what;
  char time[64];
  std::snprintf(time, sizeof time, ", %.3f ms", ms);
  summary += time;
  summary += note;
  if (in.duplicates_dropped > 0)
    summary += ", dropped " + count(in.duplicates_dropped, "duplicate point", "duplicate points");
  std::fprintf(stderr, "%s\n", summary.c_str());
}

namespace {

// The pieces with first/last indexing the whole job.
std::vector<fit::Piece<double>> job_pieces(const FitToWrite& w) {
  const io::FitReport& r = *w.report;
  std::vector<fit::Piece<double>> out(r.pieces.begin(), r.pieces.end());
  for (std::size_t k = 0; k < out.size() && k < w.piece_offset.size(); ++k) {
    out[k].first += w.piece_offset[k];
    out[k].last += w.piece_offset[k];
  }
  return out;
}

std::string title(const FitOptions& opts, const FitToWrite& w) {
  const io::FitReport& r = *w.report;
  std::string t = "kerf fit " + w.in->file + ": criterion " + r.criterion + ", tol " +
                  io::format_number(r.fit.tol) + ", " + std::to_string(r.fit.pieces) +
                  (r.fit.pieces == 1 ? " piece" : " pieces") + ", max error " +
                  io::format_number(r.fit.max_error, r.zero_below);
  if (opts.method != "optimal") t += ", method " + opts.method;
  return t;
}

}  // namespace

bool known_fit_format(const std::string& format) {
  return format == "esgi" || format == "json" || format == "gcode" || format == "svg";
}

int check_output_options(const FitOptions& opts, double& feed) {
  if (!known_fit_format(opts.format))
    return io::usage_error("--format: unknown format " + io::quoted(opts.format) +
                           " (expected esgi, json, gcode or svg)");
  if (!opts.feed.empty() && opts.format != "gcode")
    return io::usage_error("--feed: only for --format gcode");
  std::string error;
  if (!opts.feed.empty() && !io::parse_length("--feed", opts.feed, false, feed, error))
    return io::usage_error(error);
  if (opts.output.empty()) return io::usage_error("--output: empty file name");
  return kExitOk;
}

int write_fit(const FitOptions& opts, const FitToWrite& w, std::string& note) {
  const io::FitReport& r = *w.report;
  std::string text;
  if (opts.format == "json") {
    text = io::format_json(r);
  } else if (opts.format == "esgi") {
    text = io::format_esgi(r);
  } else {
    const std::vector<fit::Piece<double>> pieces = job_pieces(w);
    const Span<const Vec2<double>> pts(w.in->points.data(), w.in->points.size());
    if (opts.format == "svg") {
      io::FitPlot plot;
      plot.points = pts;
      plot.path_begin = w.in->path_begin;
      plot.pieces = {pieces.data(), pieces.size()};
      plot.tol_left = w.tol_left;
      plot.tol_right = w.tol_right;
      plot.title = title(opts, w);
      text = io::format_fit_svg(plot);
    } else {
      io::GcodeFit g;
      g.pieces = {pieces.data(), pieces.size()};
      g.points = pts;
      g.feed = w.feed;
      g.comment = title(opts, w);
      // Enough decimals that rounding keeps every point within tol (or, when
      // the fit itself is over it, within what the fit reached).
      g.decimals = 12;
      const double reached = io::written_deviation(g);
      if (!std::isfinite(reached)) {  // check_fit rules this out: a bug
        std::fprintf(stderr, "kerf: %s: internal error: a point no piece covers; nothing written\n",
                     w.in->file.c_str());
        return kExitFailure;
      }
      const double tol = std::fmax(std::fmax(w.tol_left, w.tol_right), reached);
      g.decimals = io::gcode_decimals(g, tol, 3);
      text = io::format_fit_gcode(g);
      note = ", " + std::to_string(g.decimals) + " decimals, max deviation as written " +
             io::format_number(io::written_deviation(g), r.zero_below);
    }
  }
  if (!io::write_output(opts.output, text)) {
    std::fprintf(stderr, "kerf: cannot write %s: %s\n",
                 opts.output == "-" ? "output" : opts.output.c_str(), std::strerror(errno));
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace kerf::job
