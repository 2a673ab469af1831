// `kerf fit --criterion biarc`: the fewest tangent-continuous biarcs within
// --tol of the polyline (cli/biarc_job.hpp), path by path, printed as two
// arcs per biarc sharing the joint.
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <vector>

#include "cli/biarc_job.hpp"
#include "cli/fit_command.hpp"
#include "cli/fit_job.hpp"
#include "cli/fit_write.hpp"
#include "cli/options.hpp"
#include "io/fit_output.hpp"
#include "io/point_file.hpp"

namespace kerf::cli {

namespace {

std::string count(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + ' ' + (n == 1 ? one : many);
}

int check_biarc_options(const FitOptions& opts, double& tol, bool& estimate) {
  std::string error;
  if (opts.method != "optimal")
    return usage_error("--method: " + quoted(opts.method) +
                       " is a vertex-criterion rule; --criterion biarc is always optimal");
  if (!opts.pieces.empty()) return usage_error("--pieces: not available with --criterion biarc");
  if (!opts.tol_left.empty() || !opts.tol_right.empty())
    return usage_error("--tol-left and --tol-right: --criterion biarc takes a symmetric --tol");
  if (opts.tangent_format != "vector" && opts.tangent_format != "angle")
    return usage_error("--tangent-format: unknown format " + quoted(opts.tangent_format) +
                       " (expected vector or angle)");
  if (!opts.tangents.empty() && opts.tangents != "given" && opts.tangents != "estimate")
    return usage_error("--tangents: expected given or estimate, got " + quoted(opts.tangents));
  if (!parse_length("--tol", opts.tol, false, tol, error)) return usage_error(error);
  estimate = opts.tangents == "estimate";
  return kExitOk;
}

}  // namespace

int run_fit_biarc(const FitOptions& opts) {
  double tol = 0.0;
  bool estimate = false;
  if (const int rc = check_biarc_options(opts, tol, estimate); rc != kExitOk) return rc;
  double feed = 1000.0;
  if (const int rc = check_output_options(opts, feed); rc != kExitOk) return rc;
  io::PointFile in;
  if (!read_job(opts.file, "biarc", in, {true, opts.tangent_format == "angle"})) return kExitUsage;
  if (opts.tangents == "given" && in.tangents.empty())
    return usage_error("--tangents given: " + in.file +
                       " has no tangent columns (x y tx ty, or x y angle with --tangent-format angle)");
  if (opts.tangent_format == "angle" && in.tangents.empty())
    return usage_error("--tangent-format angle: " + in.file + " has no third column");
  const bool given = !estimate && !in.tangents.empty();
  const bool fixed = opts.numeric == "fixed";
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
  report.criterion = "biarc";
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
  std::string summary = "kerf: " + in.file + ": " + count(n, "point", "points") + ", " +
                        (begins.size() > 1 ? count(begins.size(), "path", "paths") + ", " : "") +
                        count(arcs.size() / 2, "biarc", "biarcs") + " (" +
                        count(arcs.size() - lines, "arc", "arcs") +
                        (lines > 0 ? ", " + count(lines, "line", "lines") : std::string()) +
                        "), tangents " + (given ? "given" : "estimated") + ", max error " +
                        io::format_number(total.max_error, report.zero_below);
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
