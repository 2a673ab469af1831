#include "job/plan_path.hpp"

#include <algorithm>
#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "io/options.hpp"
#include "io/output_file.hpp"
#include "io/point_file.hpp"
#include "job/fit_job.hpp"

namespace kerf::job {

using io::kExitFailure;
using io::kExitOk;
using io::kExitUsage;

namespace {

// Fixed-point millimetres (1 nm), never "-0.000000".
void append_mm(std::string& out, double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6f", std::fabs(v) < 5e-7 ? 0.0 : v);
  out += buf;
}

}  // namespace

bool fit_path(const std::vector<Vec2<double>>& pts, const std::vector<double>& tols, double tol,
              Criterion criterion, std::vector<Segment<double>>& out, std::string& error,
              Numeric numeric) {
  std::vector<fit::Piece<double>> pieces;
  Status status = Status::ok;
  if (!fit_job(pts, tols, tol, criterion, pieces, error, status, numeric)) return false;
  out.clear();
  for (const fit::Piece<double>& p : pieces) out.push_back(p.segment);
  return true;
}

double fitted_length(const std::vector<Segment<double>>& path) {
  double sum = 0;
  for (const Segment<double>& g : path) {
    const Result<motion::QueuedSegment<double>> q = motion::prepare_segment<double>({g, 1.0, 0});
    if (q.ok()) sum += q.value().length;
  }
  return sum;
}

bool run_plan_path(const std::vector<Segment<double>>& path, double feed,
                   const motion::MotionConfig<double>& config, std::string& trace,
                   PlanSummary& summary, std::string& error) {
  using namespace motion;
  std::vector<QueuedSegment<double>> slots(64);
  std::vector<double> window(Interpolator<double>::jerk_window_size(config));
  Interpolator<double> ip(Span<QueuedSegment<double>>(slots.data(), slots.size()),
                          Span<double>(window.data(), window.size()));
  if (ip.configure(config) != Status::ok) {
    error = "the motion limits are out of range";
    return false;
  }
  summary = PlanSummary{};
  std::size_t next = 0;
  std::size_t cruise = 0;
  double prev_step = 0;
  double prev_change = 0;
  Vec2<double> prev_pos = path.front().start;
  Vec2<double> prev_vel{};
  const double t = config.period;
  const auto note_motion = [&](double step, Vec2<double> pos) {
    const double change = step - prev_step;
    summary.max_accel_path = std::max(summary.max_accel_path, std::fabs(change) / (t * t));
    summary.max_jerk_path = std::max(summary.max_jerk_path, std::fabs(change - prev_change) / (t * t * t));
    prev_change = change;
    const Vec2<double> vel = (pos - prev_pos) * (1 / t);
    summary.max_accel_plane = std::max(summary.max_accel_plane, (vel - prev_vel).norm() / t);
    prev_step = step;
    prev_pos = pos;
    prev_vel = vel;
  };
  double prev_s = 0;
  for (;;) {
    while (next < path.size() && ip.free_slots() > 0) {
      const Status s = ip.push({path[next], feed, static_cast<std::uint32_t>(next)});
      if (s != Status::ok) {
        error = "segment " + std::to_string(next) + " refused: " + to_string(s);
        return false;
      }
      ++next;
    }
    const Setpoint<double> p = ip.step();
    ++summary.setpoints;
    if (summary.setpoints > kMaxSetpoints) {
      error = "--period: the run would take more than " + std::to_string(kMaxSetpoints) +
              " periods";
      return false;
    }
    const double time = static_cast<double>(summary.setpoints) * t;
    if (std::fabs(p.speed - feed) <= 1e-9 * feed) ++cruise;
    note_motion(p.s - prev_s, p.position);
    prev_s = p.s;
    char head[40];
    std::snprintf(head, sizeof head, "%.9g,", time);
    trace += head;
    append_mm(trace, p.s);
    trace += ',';
    append_mm(trace, p.position.x);
    trace += ',';
    append_mm(trace, p.position.y);
    char tail[80];
    std::snprintf(tail, sizeof tail, ",%" PRId64 ",%" PRId64 ",%" PRIu64 ",%d\n", p.counts.x,
                  p.counts.y, p.segment, p.thc_lock ? 1 : 0);
    trace += tail;
    if (p.state == MotionState::done) {
      summary.time_s = time;
      summary.length_mm = p.s;
      break;
    }
  }
  note_motion(0.0, prev_pos);  // at rest after the last setpoint
  note_motion(0.0, prev_pos);
  summary.cruise_fraction =
      static_cast<double>(cruise) / static_cast<double>(summary.setpoints);
  return true;
}

int plan_file(const PlanRun& run) {
  std::string error;
  io::PointFile in;
  if (!read_job(run.file, run.criterion, in)) return kExitUsage;
  if (in.path_begin.size() > 1) {  // the interpolator runs one continuous path
    std::fprintf(stderr,
                 "kerf: %s: holds %zu paths; kerf plan runs one continuous path (kerf sim runs a job of "
                 "several, with rapids and pierces)\n",
                 in.file.c_str(), in.path_begin.size());
    return kExitUsage;
  }
  std::vector<Segment<double>> path;
  if (!fit_path(in.points, in.tols, run.tol, run.criterion, path, error, run.numeric)) {
    std::fprintf(stderr, "kerf: %s: %s\n", in.file.c_str(), error.c_str());
    return kExitFailure;
  }

  // Refused before running: runs whose trace would not fit in memory.
  if (motion::Interpolator<double>::jerk_window_size(run.config) > kMaxJerkWindow)
    return io::usage_error("--jerk: too small for --accel and --period (the S-curve would span more "
                           "than " + std::to_string(kMaxJerkWindow) + " periods)");
  if (fitted_length(path) / (run.feed / 60 * run.config.period) > static_cast<double>(kMaxSetpoints))
    return io::usage_error("--period: the run would take more than " +
                           std::to_string(kMaxSetpoints) + " periods");
  std::string trace = "t_s,s_mm,x_mm,y_mm,x_counts,y_counts,segment,thc_lock\n";
  PlanSummary sum;
  if (!run_plan_path(path, run.feed / 60, run.config, trace, sum, error)) {
    std::fprintf(stderr, "kerf: %s: %s\n", in.file.c_str(), error.c_str());
    return kExitFailure;
  }
  if (!io::write_output(run.trace, trace)) {
    std::fprintf(stderr, "kerf: --trace: cannot write %s: %s\n", run.trace.c_str(),
                 std::strerror(errno));
    return kExitFailure;
  }

  char jerk_line[128] = "";
  if (run.config.jerk > 0)
    std::snprintf(jerk_line, sizeof jerk_line,
                  "max jerk: %.6g mm/s^3 along the path (limit %.6g)\n", sum.max_jerk_path, run.config.jerk);
  char text[512];
  std::snprintf(text, sizeof text,
                "path: %zu %s, %.6f mm\n"
                "time: %.6f s, %zu setpoints\n"
                "cruise: %.1f %% of the periods at the programmed feed\n"
                "max acceleration: %.6g mm/s^2 along the path (limit %.6g), %.6g mm/s^2 in "
                "the plane\n",
                path.size(), path.size() == 1 ? "piece" : "pieces", sum.length_mm, sum.time_s,
                sum.setpoints, 100.0 * sum.cruise_fraction, sum.max_accel_path, run.config.accel,
                sum.max_accel_plane);
  // the summary goes where the trace does not
  std::FILE* to = run.trace == "-" ? stderr : stdout;
  std::fputs(text, to);
  std::fputs(jerk_line, to);
  return std::fflush(to) == 0 ? kExitOk : kExitFailure;
}

}  // namespace kerf::job
