#include "simulated/sim_job.hpp"

#include <cstdio>
#include <cstdlib>

#include "control/fit_paths.hpp"
#include "control/program_job.hpp"
#include "control/soft_limits.hpp"
#include "control/streamed_job.hpp"
#include "io/point_file.hpp"
#include "job/fit_job.hpp"
#include "job/gcode_program.hpp"
#include "job/gcode_reader.hpp"
#include "job/program_stream.hpp"

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

// A job streamed from its file (control/streamed_job.hpp): the producer
// reads and fits it path by path while the controller runs the first paths.
class StreamedSimJob final : public SimJob {
 public:
  control::JobSource& source() override { return job_.source(); }
  Vec2<double> start() const override { return start_; }
  Vec2<double> first_pierce() const override { return first_pierce_; }
  bool piece(std::size_t k, Segment<double>& out) override {
    const fit::Piece<double>* p = job_.piece(k);
    if (p != nullptr) out = p->segment;
    return p != nullptr;
  }
  void plot_points(PlotKeeper& plot) override;
  void describe(control::RunSummary& sum) const override {
    const control::StreamTotals t = job_.totals();
    sum.cut_rules = t.cut_rules;
    sum.forced_commits = t.forced_commits;
    if (t.ended) {
      sum.planned = t.segments;
      sum.paths = t.paths;
    }
    if (gcode_) control::describe_program(t.summary, sum);
  }
  const std::string& file() const override { return job_.file(); }
  void say_notes() const override {
    if (!gcode_) return;
    for (const std::string& n : job_.totals().summary.interp.notes) std::fprintf(stderr, "kerf: sim: %s\n", n.c_str());
  }

  int load(const std::string& file, const config::Config& cfg, const SimJobSettings& s);

 private:
  control::StreamedJob job_;
  control::StreamedJobSetup setup_;
  bool gcode_ = false;
  Vec2<double> start_{}, first_pierce_{};
};

int StreamedSimJob::load(const std::string& file, const config::Config& cfg, const SimJobSettings& s) {
  std::string error;
  gcode_ = job::is_gcode_path(file);
  setup_.criterion = s.criterion;
  setup_.numeric = s.numeric;
  setup_.tol = s.tol;
  setup_.feed_mm_s = s.feed / 60.0;
  setup_.max_feed_mm_s = cfg.machine.max_feed / 60.0;
  setup_.rules = cfg.cut.rules;
  setup_.limits = control::soft_limits_of(cfg.machine);
  setup_.torch_off = setup_.outputs_off = s.dry_run;
  if (gcode_) {
    // The simulator keeps the machine state in memory: it starts from the
    // configured file's offsets (if any) and never writes it.
    if (!cfg.machine.state.empty() && !job::load_machine_state(cfg.machine.state, setup_.state, error)) {
      std::fprintf(stderr, "kerf: sim: machine.state: %s\n", error.c_str());
      return 2;
    }
    setup_.interp = config::interp_settings(cfg, false);
  }
  // Refused before anything moves: a file that cannot be read, or a bad
  // line or a move outside the table within the first ring's worth.
  int rc = job_.open(file, setup_, error);
  if (rc == 0) rc = job_.prime(error);
  if (rc != 0) {
    if (!error.empty()) std::fprintf(stderr, "%s\n", error.c_str());
    return rc;
  }
  control::JobSource& src = job_.source();
  if (src.segment_count() == 0) {
    std::fprintf(stderr, "kerf: %s: no path to cut\n", file.c_str());
    return 2;
  }
  first_pierce_ = src.locate(0).start;
  start_ = gcode_ ? Vec2<double>{cfg.sim.start[0], cfg.sim.start[1]} : first_pierce_;
  return 0;
}

void StreamedSimJob::plot_points(PlotKeeper& plot) {
  // The input points read again from the file's start, up to the plot's budget.
  if (gcode_) {
    std::unique_ptr<job::ProgramStream> program;
    std::string error;
    if (!job::open_program_stream(job_.file(), setup_.interp, setup_.state, program, error)) return;
    job::ProgramPiece path;
    job::ProgramAction action;
    std::size_t p = 0;
    for (job::ProgramStream::Next n; (n = program->next(path, action)) != job::ProgramStream::Next::end &&
                                     n != job::ProgramStream::Next::error;)
      if (n == job::ProgramStream::Next::path && !plot.add_points(p++, path.points.data(), path.points.size())) break;
    return;
  }
  std::FILE* in = std::fopen(job_.file().c_str(), "rb");
  if (in == nullptr) return;
  char line[4096];
  std::size_t p = 0;
  bool in_path = false;
  while (std::fgets(line, sizeof line, in) != nullptr) {
    char* end = nullptr;
    const double x = std::strtod(line, &end);
    if (end == line) {  // a blank or comment line: a blank one ends the path
      if (in_path && (line[0] == '\n' || line[0] == '\r')) ++p, in_path = false;
      continue;
    }
    const char* rest = end;
    while (*rest == ' ' || *rest == '\t' || *rest == ',') ++rest;
    const Vec2<double> pt{x, std::strtod(rest, nullptr)};
    in_path = true;
    if (!plot.add_points(p, &pt, 1)) break;
  }
  std::fclose(in);
}

}  // namespace

int load_sim_job(const std::string& file, const config::Config& cfg, const SimJobSettings& s,
                 std::unique_ptr<SimJob>& out) {
  if (!file.empty() && !s.whole) {  // the demo job is compiled in (43 segments): held whole
    auto streamed = std::make_unique<StreamedSimJob>();
    if (const int rc = streamed->load(file, cfg, s); rc != 0) return rc;
    out = std::move(streamed);
    return 0;
  }
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
