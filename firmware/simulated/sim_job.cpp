#include "simulated/sim_job.hpp"

#include <cstdio>

#include "control/fit_paths.hpp"
#include "control/program_job.hpp"
#include "control/soft_limits.hpp"
#include "io/point_file.hpp"
#include "job/fit_job.hpp"
#include "job/gcode_program.hpp"

namespace kerf::simulated {

namespace {

const char* const kDemoJob =
#include "demo_job.inc"
    ;

// A job read and fitted whole before it runs.
class WholeSimJob final : public SimJob {
 public:
  control::JobSource& source() override { return *source_; }
  Vec2<double> start() const override { return start_; }
  Vec2<double> first_pierce() const override { return fitted_.job.paths.front().start; }
  bool piece(std::size_t k, Segment<double>& out) override {
    if (k >= fitted_.pieces.size()) return false;
    out = fitted_.pieces[k].segment;
    return true;
  }
  void plot_points(PlotKeeper& plot) override {
    for (std::size_t p = 0; p < fitted_.job.paths.size(); ++p) {
      const std::size_t b = in_.path_begin.empty() ? 0 : in_.path_begin[p];
      const std::size_t e = p + 1 < in_.path_begin.size() ? in_.path_begin[p + 1] : in_.points.size();
      if (!plot.add_points(p, in_.points.data() + b, e - b)) break;
    }
  }
  void describe(control::RunSummary& sum) const override {
    sum.cut_rules = fitted_.cut_rules;
    sum.forced_commits = fitted_.job.forced_commits;
    if (gcode_) control::describe_program(prog_, sum);
  }
  const std::string& file() const override { return in_.file; }

  int load(const std::string& file, const config::Config& cfg, const SimJobSettings& s);

 private:
  io::PointFile in_;
  job::GcodeProgram prog_;
  bool gcode_ = false;
  control::FittedJob fitted_;
  Vec2<double> start_{};
  std::unique_ptr<control::WholeJobSource> source_;
};

int WholeSimJob::load(const std::string& file, const config::Config& cfg, const SimJobSettings& s) {
  std::string error;
  const bool demo = file.empty();
  gcode_ = !demo && job::is_gcode_path(file);
  if (gcode_) {
    // The simulator keeps the machine state in memory: it starts from the
    // configured file's offsets (if any) and never writes it.
    job::MachineState state;
    if (!cfg.machine.state.empty() && !job::load_machine_state(cfg.machine.state, state, error)) {
      std::fprintf(stderr, "kerf: sim: machine.state: %s\n", error.c_str());
      return 2;
    }
    if (!job::read_gcode_program(file, config::interp_settings(cfg, false), state, prog_, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 2;
    }
    for (const std::string& n : prog_.interp.notes) std::fprintf(stderr, "kerf: sim: %s\n", n.c_str());
    in_ = prog_.points;
  } else if (demo) {
    in_ = io::parse_points(kDemoJob, "<demo job>");
    if (!in_.ok) {
      std::fprintf(stderr, "%s\n", io::describe_error(in_).c_str());
      return 1;
    }
  } else if (!job::read_job(file, s.criterion, in_)) {
    return 2;
  }
  if (const int rc = gcode_ ? control::fit_program_or_say(prog_, s.criterion, s.tol, s.feed / 60.0,
                                                          cfg.machine.max_feed / 60.0, fitted_, s.numeric, &cfg.cut.rules)
                            : control::fit_paths_or_say(in_, s.criterion, s.tol, s.feed / 60.0, fitted_, s.numeric,
                                                        &cfg.cut.rules);
      rc != 0)
    return rc;
  // The whole job inside the table before anything moves, from where the
  // simulated machine starts.
  start_ = gcode_ ? Vec2<double>{cfg.sim.start[0], cfg.sim.start[1]} : fitted_.job.paths.front().start;
  if (!control::check_soft_limits(fitted_, in_, control::soft_limits_of(cfg.machine), &start_, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 2;
  }
  if (s.dry_run) control::hold_outputs_off(fitted_.job, true);
  source_ = std::make_unique<control::WholeJobSource>(fitted_.job);
  return 0;
}

}  // namespace

int load_sim_job(const std::string& file, const config::Config& cfg, const SimJobSettings& s,
                 std::unique_ptr<SimJob>& out) {
  auto whole = std::make_unique<WholeSimJob>();
  if (const int rc = whole->load(file, cfg, s); rc != 0) return rc;
  out = std::move(whole);
  return 0;
}

bool open_sim_journal(const std::string& path, bool resume, control::JobSource& source, Vec2<double> first_pierce,
                      std::unique_ptr<control::Journal>& out, control::ResumePoint& from) {
  from = control::ResumePoint{};
  from.from = first_pierce;
  out.reset();
  if (path.empty()) return true;
  std::string error;
  out = resume ? control::Journal::resume(path, source.id(), error) : control::Journal::create(path, source.id(), error);
  if (!out) {
    std::fprintf(stderr, "kerf: --journal: %s\n", error.c_str());
    return false;
  }
  if (resume) from = control::resume_point(source, out->state());
  return true;
}

}  // namespace kerf::simulated
