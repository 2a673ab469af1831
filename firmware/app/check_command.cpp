#include "app/check_command.hpp"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "app/job_input.hpp"
#include "control/job_time.hpp"
#include "control/machine_config.hpp"
#include "control/program_job.hpp"
#include "control/soft_limits.hpp"
#include "io/input_file.hpp"
#include "io/options.hpp"
#include "io/output_file.hpp"
#include "io/run_svg.hpp"

namespace kerf::app {

namespace {

std::string range(double lo, double hi, bool on) {
  char text[80];
  if (!on) return "unlimited";
  std::snprintf(text, sizeof text, "%.3f .. %.3f", lo, hi);
  return text;
}

control::JobTimeSettings time_settings(const config::Config& cfg, Vec2<double> start) {
  control::JobTimeSettings s;
  s.servo_period_s = cfg.machine.servo_period;
  s.cycle_s = cfg.machine.cycle;
  s.accel_mm_s2 = cfg.machine.accel;
  s.vad = cfg.cut.rules.vad / 100.0;
  s.counts_per_mm = cfg.machine.axes.empty() ? 1000.0 : cfg.machine.axes.front().counts_per_mm;
  s.rapid_feed_mm_s = cfg.machine.rapid_feed / 60.0;
  s.pierce_delay_s = cfg.cut.pierce_delay;
  s.operator_delay_s = cfg.sim.operator_delay;
  s.start = start;
  s.z = config::z_limits(cfg.machine);
  return s;
}

io::RunPlot plot_of(const JobInput& in, const config::Config& cfg, const std::string& who) {
  io::RunPlot plot;
  const io::PointFile& src = in.source();
  const control::FittedJob& f = in.fitted;
  for (std::size_t p = 0; p < f.job.paths.size(); ++p) {
    const std::size_t b = f.path_point[p];
    const std::size_t e = p + 1 < f.path_point.size() ? f.path_point[p + 1] : src.points.size();
    plot.paths.emplace_back(src.points.begin() + static_cast<std::ptrdiff_t>(b),
                            src.points.begin() + static_cast<std::ptrdiff_t>(std::max(b, e)));
  }
  for (const fit::Piece<double>& piece : f.pieces) plot.pieces.push_back(piece.segment);
  plot.piece_path = f.piece_path;
  plot.tol = cfg.fit.tol;
  const motion::SoftLimits<double> l = control::soft_limits_of(cfg.machine);
  plot.table = control::fully_limited(cfg.machine);
  plot.table_lo = {l.min[0], l.min[1]};
  plot.table_hi = {l.max[0], l.max[1]};
  plot.title = who + " check: " + src.file;
  return plot;
}

}  // namespace

CLI::App* add_check_command(CLI::App& app, CheckOptions& o, bool config_required) {
  CLI::App* c = app.add_subcommand(
      "check", "Check a job before it runs, moving nothing: segments, pierces, the time it will take, its extents "
               "against the soft limits, and what a run would refuse (exit 2 then)");
  CLI::Option* config = c->add_option("--config", o.config, "Machine configuration (TOML)")->type_name("FILE");
  if (config_required) config->required();
  c->add_option("--plot", o.plot, "Write an SVG plot of the job and the table's outline here")->type_name("P.svg");
  c->add_option("job", o.job, "Point file or G-code program")->type_name("JOB")->required();
  return c;
}

int run_check(const CheckOptions& opts, const char* who, RunCheck check) {
  std::string error;
  config::Config cfg = config::defaults();
  if (!io::input_readable(opts.config) || !io::input_readable(opts.job)) return io::kExitUsage;
  if (!opts.config.empty() && !config::load(opts.config, cfg, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return io::kExitUsage;
  }
  const std::string says = std::string(who) + ": check";
  if (check && !check(cfg, error)) {
    std::fprintf(stderr, "%s: %s\n", says.c_str(), error.c_str());
    return io::kExitFailure;
  }
  JobInput in;
  std::string cannot_run;
  if (const int rc = read_and_fit(cfg, opts.job, check != nullptr, says.c_str(), in, &cannot_run); rc != 0) return rc;
  const control::FittedJob& f = in.fitted;
  const std::string file = in.source().file;
  // What a run would refuse, each on stderr.
  int refusals = 0;
  const auto refuse = [&](const std::string& why) {
    std::fprintf(stderr, "%s\n", why.c_str());
    ++refusals;
  };
  if (!cannot_run.empty()) refuse(cannot_run);
  // kerf run: the machine's position is not known before the run; kerf-sim: [sim] start.
  const Vec2<double> sim_start{cfg.sim.start[0], cfg.sim.start[1]};
  const Vec2<double> start = in.gcode ? sim_start : f.job.paths.front().start;
  const motion::SoftLimits<double> limits = control::soft_limits_of(cfg.machine);
  if (!control::check_soft_limits(f, in.source(), limits, check ? nullptr : &start, error)) refuse(error);
  control::Job job = f.job;
  if (cfg.bench.enabled) control::hold_outputs_off(job, false);
  const control::JobTime t = control::estimate_job_time(job, time_settings(cfg, start));
  if (!t.ok) refuse(file + ": a segment the board's planner refuses");

  std::printf("%s: %s: %zu segments in %zu paths, %zu pierces%s\n", who, file.c_str(), job.segment_count(),
              job.paths.size(), t.pierces, in.gcode && in.prog.dry_run ? " (no M3/M4: a dry run)" : "");
  std::printf("%s: time %.3f s: cut %.3f s, travel %.3f s, pierces %.3f s, dwells, pauses and waits %.3f s "
              "(travel from (%.3f, %.3f))\n",
              who, t.total_s, t.cut_s, t.travel_s, t.pierce_s, t.actions_s, start.x, start.y);
  const motion::Extent<double> e = control::job_extent(f, &start);
  std::printf("%s: extents X %s, Y %s mm; soft limits X %s, Y %s\n", who, range(e.lo.x, e.hi.x, true).c_str(),
              range(e.lo.y, e.hi.y, true).c_str(), range(limits.min[0], limits.max[0], limits.on[0]).c_str(),
              range(limits.min[1], limits.max[1], limits.on[1]).c_str());
  if (!control::fully_limited(cfg.machine))
    std::fprintf(stderr, "%s: %s: machine.axis: x and y need min and max (soft limits) for a real table\n",
                 says.c_str(), cfg.file.c_str());
  if (!opts.plot.empty() && !io::write_output(opts.plot, io::format_run_svg(plot_of(in, cfg, who)))) {
    std::fprintf(stderr, "%s: --plot: cannot write %s: %s\n", who, opts.plot.c_str(), std::strerror(errno));
    return io::kExitFailure;
  }
  std::printf("%s: %s\n", who, refusals == 0 ? "ok: the job would run" : "REFUSED: the run would not start");
  return refusals == 0 ? io::kExitOk : io::kExitUsage;
}

}  // namespace kerf::app
