#include "app/plan_command.hpp"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "app/fit_command.hpp"
#include "app/fit_options.hpp"
#include "job/fit_job.hpp"
#include "io/options.hpp"
#include "job/plan_path.hpp"
#include "io/output_file.hpp"
#include "io/point_file.hpp"

namespace kerf::cli {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

CLI::App* add_plan_command(CLI::App& app, PlanOptions& opts) {
  CLI::App* plan = add_fitting_command(
      app, "plan", "Fit the points, then run the constant-feed interpolator and write its trace", opts.tol);
  plan->add_option("--criterion", opts.criterion,
                   "vertex (points within tol of their arc) or band (the whole arc within tol)")
      ->type_name("NAME")
      ->capture_default_str();
  add_numeric_option(plan, opts.numeric);
  plan->add_option("--feed", opts.feed, "Programmed feed, mm/min")->type_name("MM_PER_MIN");
  plan->add_option("--period", opts.period, "Servo period, s")->type_name("S");
  plan->add_option("--accel", opts.accel, "Acceleration limit along the path, mm/s^2")
      ->type_name("MM_S2");
  plan->add_option("--jerk", opts.jerk, "Jerk limit, mm/s^3: S-curve ramps (default: trapezoidal)")
      ->type_name("MM_S3");
  plan->add_option("--corner", opts.corner,
                   "Tangent turns above this many degrees are corners (slowed down)")
      ->type_name("DEG")
      ->capture_default_str();
  plan->add_option("--counts-per-mm", opts.counts_per_mm, "Drive counts per mm, both axes")
      ->type_name("N");
  plan->add_option("--trace", opts.trace, "Setpoint trace (CSV) to write; - for stdout")
      ->type_name("OUT.csv");
  add_points_file(plan, opts.file);
  return plan;
}

int run_plan(const PlanOptions& opts) {
  std::string error;
  double tol = 0, feed = 0, period = 0, accel = 0, corner = 0, cpm = 0;
  if (!parse_length("--tol", opts.tol, false, tol, error)) return usage_error(error);
  const std::optional<Criterion> criterion = parse_criterion(opts.criterion);
  if (!criterion) return usage_error(unknown_criterion(opts.criterion));
  const std::optional<Numeric> numeric = parse_numeric(opts.numeric);
  if (!numeric) return usage_error(unknown_numeric(opts.numeric));
  if (!parse_length("--feed", opts.feed, false, feed, error) ||
      !parse_length("--period", opts.period, false, period, error) ||
      !parse_length("--accel", opts.accel, false, accel, error) ||
      !parse_length("--corner", opts.corner, true, corner, error) ||
      !parse_length("--counts-per-mm", opts.counts_per_mm, false, cpm, error))
    return usage_error(error);
  double jerk = 0;
  if (!opts.jerk.empty() && !parse_length("--jerk", opts.jerk, true, jerk, error))
    return usage_error(error);
  if (corner > 180) return usage_error("--corner: must be at most 180, got " + opts.corner);
  if (opts.trace.empty()) return usage_error("--trace: required");

  io::PointFile in;
  if (!read_job(opts.file, *criterion, in)) return kExitUsage;
  if (in.path_begin.size() > 1) {  // the interpolator runs one continuous path
    std::fprintf(stderr,
                 "kerf: %s: holds %zu paths; kerf plan runs one continuous path (kerf sim runs a job of "
                 "several, with rapids and pierces)\n",
                 in.file.c_str(), in.path_begin.size());
    return kExitUsage;
  }
  std::vector<Segment<double>> path;
  if (!fit_path(in.points, in.tols, tol, *criterion, path, error, *numeric)) {
    std::fprintf(stderr, "kerf: %s: %s\n", in.file.c_str(), error.c_str());
    return kExitFailure;
  }

  motion::MotionConfig<double> config;
  config.period = period;
  config.accel = accel;
  config.jerk = jerk;
  config.corner_angle = corner * kPi / 180;
  config.counts_per_mm = {cpm, cpm};
  // Refused before running: runs whose trace would not fit in memory.
  if (motion::Interpolator<double>::jerk_window_size(config) > kMaxJerkWindow)
    return usage_error("--jerk: too small for --accel and --period (the S-curve would span more "
                       "than " + std::to_string(kMaxJerkWindow) + " periods)");
  if (fitted_length(path) / (feed / 60 * period) > static_cast<double>(kMaxSetpoints))
    return usage_error("--period: the run would take more than " +
                       std::to_string(kMaxSetpoints) + " periods");
  std::string trace = "t_s,s_mm,x_mm,y_mm,x_counts,y_counts,segment\n";
  PlanSummary sum;
  if (!run_plan_path(path, feed / 60, config, trace, sum, error)) {
    std::fprintf(stderr, "kerf: %s: %s\n", in.file.c_str(), error.c_str());
    return kExitFailure;
  }
  if (!io::write_output(opts.trace, trace)) {
    std::fprintf(stderr, "kerf: --trace: cannot write %s: %s\n", opts.trace.c_str(),
                 std::strerror(errno));
    return kExitFailure;
  }

  char jerk_line[128] = "";
  if (jerk > 0)
    std::snprintf(jerk_line, sizeof jerk_line,
                  "max jerk: %.6g mm/s^3 along the path (limit %.6g)\n", sum.max_jerk_path, jerk);
  char text[512];
  std::snprintf(text, sizeof text,
                "path: %zu %s, %.6f mm\n"
                "time: %.6f s, %zu setpoints\n"
                "cruise: %.1f %% of the periods at the programmed feed\n"
                "max acceleration: %.6g mm/s^2 along the path (limit %.6g), %.6g mm/s^2 in "
                "the plane\n",
                path.size(), path.size() == 1 ? "piece" : "pieces", sum.length_mm, sum.time_s,
                sum.setpoints, 100.0 * sum.cruise_fraction, sum.max_accel_path, accel,
                sum.max_accel_plane);
  // the summary goes where the trace does not
  std::FILE* to = opts.trace == "-" ? stderr : stdout;
  std::fputs(text, to);
  std::fputs(jerk_line, to);
  return std::fflush(to) == 0 ? kExitOk : kExitFailure;
}

}  // namespace kerf::cli
