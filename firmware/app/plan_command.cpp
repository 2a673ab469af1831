#include "app/plan_command.hpp"

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "app/fit_command.hpp"
#include "app/fit_options.hpp"
#include "io/input_file.hpp"
#include "io/options.hpp"
#include "job/plan_path.hpp"

namespace kerf::app {

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
  if (!io::input_readable(opts.file)) return io::kExitUsage;
  std::string error;
  double tol = 0, feed = 0, period = 0, accel = 0, corner = 0, cpm = 0;
  if (!io::parse_length("--tol", opts.tol, false, tol, error)) return io::usage_error(error);
  const std::optional<job::Criterion> criterion = job::parse_criterion(opts.criterion);
  if (!criterion) return io::usage_error(job::unknown_criterion(opts.criterion));
  const std::optional<job::Numeric> numeric = job::parse_numeric(opts.numeric);
  if (!numeric) return io::usage_error(job::unknown_numeric(opts.numeric));
  if (!io::parse_length("--feed", opts.feed, false, feed, error) ||
      !io::parse_length("--period", opts.period, false, period, error) ||
      !io::parse_length("--accel", opts.accel, false, accel, error) ||
      !io::parse_length("--corner", opts.corner, true, corner, error) ||
      !io::parse_length("--counts-per-mm", opts.counts_per_mm, false, cpm, error))
    return io::usage_error(error);
  double jerk = 0;
  if (!opts.jerk.empty() && !io::parse_length("--jerk", opts.jerk, true, jerk, error))
    return io::usage_error(error);
  if (corner > 180) return io::usage_error("--corner: must be at most 180, got " + opts.corner);
  if (opts.trace.empty()) return io::usage_error("--trace: required");

  job::PlanRun run;
  run.file = opts.file;
  run.criterion = *criterion;
  run.numeric = *numeric;
  run.tol = tol;
  run.feed = feed;
  run.config.period = period;
  run.config.accel = accel;
  run.config.jerk = jerk;
  run.config.corner_angle = corner * kPi / 180;
  run.config.counts_per_mm = {cpm, cpm};
  run.trace = opts.trace;
  return job::plan_file(run);
}

}  // namespace kerf::app
