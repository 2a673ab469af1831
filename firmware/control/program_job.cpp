#include "control/program_job.hpp"

#include <algorithm>
#include <cstdio>

#include "job/fit_job.hpp"

namespace kerf::control {

int fit_program_or_say(const job::GcodeProgram& prog, job::Criterion criterion, double tol, double feed_mm_s,
                       double max_feed_mm_s, FittedJob& out, job::Numeric numeric) {
  out = FittedJob{};
  const io::PointFile& in = prog.points;
  const std::vector<std::size_t>& begins = in.path_begin;
  for (std::size_t p = 0; p < begins.size(); ++p) {
    const std::size_t b = begins[p];
    const std::size_t e = p + 1 < begins.size() ? begins[p + 1] : in.points.size();
    const std::vector<Vec2<double>> pts(in.points.begin() + static_cast<std::ptrdiff_t>(b),
                                        in.points.begin() + static_cast<std::ptrdiff_t>(e));
    const job::ProgramPath& pp = prog.paths[p];
    const double path_tol = pp.tol > 0 ? std::min(pp.tol, tol) : tol;
    std::vector<fit::Piece<double>> pieces;
    std::string why;
    Status status = Status::ok;
    if (!job::fit_job(pts, {}, path_tol, criterion, pieces, why, status, numeric)) {
      std::fprintf(stderr, "kerf: %s: path %zu (line %zu): %s\n", in.file.c_str(), p + 1, in.point_lines[b],
                   why.c_str());
      return status == Status::invalid_argument || status == Status::degenerate ? 2 : 1;
    }
    // Each piece at the slowest feed programmed along it (mm/min per point; 0: the default).
    auto feed_of = [&](const fit::Piece<double>& piece) {
      double f = 0;
      for (std::size_t k = b + piece.first + 1; k <= b + piece.last && k < prog.point_feed.size(); ++k) {
        const double v = prog.point_feed[k] > 0 ? prog.point_feed[k] / 60.0 : feed_mm_s;
        f = f == 0 ? v : std::min(f, v);
      }
      if (f == 0) f = pp.feed_mm_min > 0 ? pp.feed_mm_min / 60.0 : feed_mm_s;
      return std::min(f, max_feed_mm_s);
    };
    CutPath path;
    path.start = pts.front();
    path.torch = pp.torch;
    path.pierce_delay_s = pp.pierce_delay_s;
    for (const fit::Piece<double>& piece : pieces) {
      hal::SegmentCommand c;
      c.kind = piece.segment.kind;
      c.end = piece.segment.end;
      c.centre = piece.segment.centre;
      c.dir = piece.segment.dir;
      c.feed = feed_of(piece);
      c.torch = pp.torch;
      path.segments.push_back(c);
      out.pieces.push_back(piece);
      out.piece_path.push_back(p);
    }
    out.job.paths.push_back(std::move(path));
  }
  out.job.actions = prog.actions;
  return 0;
}

bool machine_can_run(const job::GcodeProgram& prog, std::string& error) {
  for (const JobAction& a : prog.actions) {
    const char* what = a.kind == job::CanonKind::digital_out  ? "a digital output"
                       : a.kind == job::CanonKind::analog_out ? "an analog output"
                       : a.kind == job::CanonKind::wait_input ? "a wait on an input (M66)"
                                                              : nullptr;
    if (what == nullptr) continue;
    error = prog.points.file + ":" + std::to_string(a.line) + ": " + what +
            ": kerf run has no program output or input lines yet (only the torch); kerf sim runs it";
    return false;
  }
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
