#include "control/program_job.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "control/cut_rules.hpp"
#include "job/fit_job.hpp"

namespace kerf::control {

// z axis: the program's moves between paths as link commands (torch off;
// feed 0 means rapid, which the controller fills in; a z move's XY is set
// when it is sent). XY ends go on the link's grid, as the fitted paths' do:
// a rapid that rounds to nothing is then seen as nothing (the board refuses
// a zero-length line).
void append_moves(const std::vector<job::ProgramMove>& moves, double max_feed_mm_s,
                  std::vector<hal::SegmentCommand>& out) {
  for (const job::ProgramMove& m : moves) {
    hal::SegmentCommand c;
    c.kind = SegmentKind::line;
    const double per_mm = kLinkGrid.per_mm;
    c.end = {std::round(m.xy.x * per_mm) / per_mm, std::round(m.xy.y * per_mm) / per_mm};
    c.z_move = m.z;
    c.z = m.z_end;
    c.feed = m.feed_mm_min > 0 ? std::min(m.feed_mm_min / 60.0, max_feed_mm_s) : 0.0;
    c.torch = false;
    out.push_back(c);
  }
}

int fit_program_path(const io::PointFile& one, const std::vector<double>& feed, const job::ProgramPath& pp,
                     std::size_t p, const PathFitSettings& s, FittedJob& f, std::string& error) {
  // The path alone through fit_paths, at its own tolerance: the same fit
  // and the same segments on the link's grid as a point file's.
  Status status = Status::ok;
  const double tol = pp.tol > 0 ? std::min(pp.tol, s.tol) : s.tol;
  if (!fit_paths(one, s.criterion, tol, s.feed_mm_s, f, error, status, s.numeric)) {
    if (f.job.paths.empty() && status == Status::invalid_argument && error.find("shorter than the link") != std::string::npos) {
      f = FittedJob{};  // a path shorter than a count: nothing to cut; its moves go on
      error.clear();
      return 0;
    }
    if (error.compare(0, 7, "path 1 ") == 0) error = "path " + std::to_string(p + 1) + error.substr(6);
    return status == Status::invalid_argument || status == Status::degenerate ? 2 : 1;
  }
  // Each segment at the slowest feed programmed along its piece (mm/min per point; 0: the default).
  auto feed_of = [&](const fit::Piece<double>& piece) {
    double v = 0;
    for (std::size_t k = piece.first + 1; k <= piece.last && k < feed.size(); ++k) {
      const double f_k = feed[k] > 0 ? feed[k] / 60.0 : s.feed_mm_s;
      v = v == 0 ? f_k : std::min(v, f_k);
    }
    if (v == 0) v = pp.feed_mm_min > 0 ? pp.feed_mm_min / 60.0 : s.feed_mm_s;
    return std::min(v, s.max_feed_mm_s);
  };
  CutPath& path = f.job.paths.front();
  path.torch = pp.torch;
  path.pierce_delay_s = pp.pierce_delay_s;
  append_moves(pp.before, s.max_feed_mm_s, path.before);
  append_moves(pp.after, s.max_feed_mm_s, path.after);
  for (std::size_t k = 0; k < path.segments.size(); ++k) {
    path.segments[k].feed = feed_of(f.pieces[k]);
    path.segments[k].torch = pp.torch;
  }
  return 0;
}

int fit_program_or_say(const job::GcodeProgram& prog, job::Criterion criterion, double tol, double feed_mm_s,
                       double max_feed_mm_s, FittedJob& out, job::Numeric numeric,
                       const config::CutRules* rules) {
  out = FittedJob{};
  const io::PointFile& in = prog.points;
  const std::vector<std::size_t>& begins = in.path_begin;
  const PathFitSettings settings{criterion, numeric, tol, feed_mm_s, max_feed_mm_s};
  // kept_before[k]: how many paths before program path k reach the job (a
  // path shorter than the link's grid does not), for the actions' places.
  std::vector<std::size_t> kept_before(begins.size() + 1, 0);
  std::vector<hal::SegmentCommand> carry;  // the moves of paths too short to keep
  for (std::size_t p = 0; p < begins.size(); ++p) {
    kept_before[p] = out.job.paths.size();
    const auto b = static_cast<std::ptrdiff_t>(begins[p]);
    const auto e = static_cast<std::ptrdiff_t>(p + 1 < begins.size() ? begins[p + 1] : in.points.size());
    const job::ProgramPath& pp = prog.paths[p];
    io::PointFile one;
    one.file = in.file;
    one.points.assign(in.points.begin() + b, in.points.begin() + e);
    one.point_lines.assign(in.point_lines.begin() + b, in.point_lines.begin() + e);
    std::vector<double> feed;
    if (static_cast<std::size_t>(b) < prog.point_feed.size())
      feed.assign(prog.point_feed.begin() + b, prog.point_feed.begin() + std::min<std::ptrdiff_t>(e, static_cast<std::ptrdiff_t>(prog.point_feed.size())));
    FittedJob f;
    std::string error;
    if (const int rc = fit_program_path(one, feed, pp, p, settings, f, error); rc != 0) {
      std::fprintf(stderr, "kerf: %s: %s\n", in.file.c_str(), error.c_str());
      return rc;
    }
    if (f.job.paths.empty()) {
      append_moves(pp.before, max_feed_mm_s, carry);
      append_moves(pp.after, max_feed_mm_s, carry);
      continue;
    }
    CutPath& path = f.job.paths.front();
    path.before.insert(path.before.begin(), carry.begin(), carry.end());
    carry.clear();
    for (std::size_t k = 0; k < path.segments.size(); ++k) {
      out.pieces.push_back(f.pieces[k]);
      out.piece_path.push_back(out.job.paths.size());
    }
    out.lines_for_arcs += f.lines_for_arcs;
    out.job.forced_commits += f.job.forced_commits;
    out.job.paths.push_back(std::move(path));
    out.path_point.push_back(static_cast<std::size_t>(b));
  }
  kept_before[begins.size()] = out.job.paths.size();
  if (!out.job.paths.empty()) out.job.paths.back().after.insert(out.job.paths.back().after.end(), carry.begin(), carry.end());
  if (out.job.paths.empty()) {
    std::fprintf(stderr, "kerf: %s: every path is shorter than the link's resolution (0.001 mm)\n", in.file.c_str());
    return 2;
  }
  out.job.actions = prog.actions;
  for (JobAction& a : out.job.actions) a.before_path = kept_before[a.before_path];
  if (rules) {
    out.cut_rules = apply_cut_rules(out, *rules);
    say_cut_rules(in.file, out.cut_rules, *rules);
  }
  return 0;
}

namespace {

bool has(const std::vector<int>& numbers, int n) { return std::find(numbers.begin(), numbers.end(), n) != numbers.end(); }

}  // namespace

std::string cannot_run(const JobAction& a, const MachineIo& io) {
  const std::string n = std::to_string(a.index);
  switch (a.kind) {
    case job::CanonKind::digital_out:
      if (io.bench) return "digital output " + n + ": a bench ([bench] enabled = true) runs motion only";
      return has(io.outputs, a.index) ? ""
                                      : "digital output " + n + " has no line: add [[gpio.output]] with number = " +
                                            n + " (and its offset or name) to the configuration";
    case job::CanonKind::wait_input:
      return has(io.inputs, a.index) ? ""
                                     : "input " + n + " (M66 P" + n + ") has no line: add [[gpio.input]] with number = " +
                                           n + " (and its offset or name) to the configuration";
    case job::CanonKind::analog_out:
      return has(io.analog_ignore, a.index) ? ""
                                            : "analog output " + n + " (M67/M68 E" + n +
                                                  "): kerf has no analog lines: add " + n +
                                                  " to [analog] ignore to run the program without it";
    default: return "";
  }
}

bool machine_can_run(job::GcodeProgram& prog, const MachineIo& io, std::string& error) {
  const std::string& file = prog.points.file;
  for (const JobAction& a : prog.actions) {
    const std::string why = cannot_run(a, io);
    if (!why.empty()) {
      error = file + ":" + std::to_string(a.line) + ": " + why;
      return false;
    }
  }
  for (const auto& [n, line] : prog.interp.analog_inputs)
    if (!has(io.analog_ignore, n)) {
      const std::string k = std::to_string(n);
      error = file + ":" + std::to_string(line) + ": analog input " + k + " (M66 E" + k +
              "): kerf has no analog lines: add " + k + " to [analog] ignore to run the program without it";
      return false;
    }
  // Each ignored analog number, once, in the notes (printed at load and in the report).
  std::vector<std::pair<std::string, int>> noted;  // once a number, at its first line
  auto note = [&](const char* what, int n, std::size_t line) {
    if (std::find(noted.begin(), noted.end(), std::make_pair(std::string(what), n)) != noted.end()) return;
    noted.emplace_back(what, n);
    const std::string text = std::string(what) + " " + std::to_string(n) +
                             " ignored ([analog] ignore), first at line " + std::to_string(line);
    if (std::find(prog.interp.notes.begin(), prog.interp.notes.end(), text) == prog.interp.notes.end())
      prog.interp.notes.push_back(text);
  };
  for (const JobAction& a : prog.actions)
    if (a.kind == job::CanonKind::analog_out) note("analog output", a.index, a.line);
  for (const auto& [n, line] : prog.interp.analog_inputs) note("analog input", n, line);
  return true;
}

void describe_program(const job::GcodeProgram& prog, RunSummary& sum) {
  sum.gcode = true;
  sum.dry_run = prog.dry_run;
  sum.notes = prog.interp.notes;
  sum.constructs.clear();
  for (const auto& [name, c] : prog.interp.constructs) sum.constructs.push_back({name, c.handling, c.count, c.first_line});
}

}  // namespace kerf::control
