#include "control/fit_paths.hpp"

#include "control/cut_rules.hpp"
#include "control/job_source.hpp"
#include "control/path_stream.hpp"
#include "job/fit_job.hpp"

#include <cstdio>

namespace kerf::control {

namespace {

// A path longer than the fit's window, in double by the vertex criterion,
// and without a repeated point (the window drops repeats, which would shift
// the pieces' point numbers): fitted in the bounded window
// (control/path_stream.hpp). Shorter paths are the window's whole-path case:
// fitted here directly, the same bytes. The band criterion's window rebuilds
// its region for each point (about 20k points/s, tests/bench kerf_bench_stream):
// on tball-pocket's long paths that was 5 times the whole-path fit, so band
// paths are fitted whole until the window keeps its region.
bool streams(const io::PointFile& in, std::size_t b, std::size_t e, job::Criterion criterion, job::Numeric numeric) {
  if (e - b <= PathStreamFitter::kMaxWindow || numeric != job::Numeric::floating || !in.tols.empty()) return false;
  if (criterion != job::Criterion::vertex) return false;
  for (std::size_t k = b + 1; k < e; ++k)
    if (in.points[k] == in.points[k - 1]) return false;
  return true;
}

bool fit_in_window(const io::PointFile& in, std::size_t p, std::size_t b, std::size_t e, job::Criterion criterion,
                   double tol, double feed_mm_s, PathStreamFitter& window, FittedJob& out, std::string& error,
                   Status& status) {
  if (!window.start(criterion, job::Numeric::floating, feed_mm_s, PathStreamFitter::kMaxWindow, error)) {
    status = Status::invalid_argument;
    return false;
  }
  window.begin_path(in.file, p, tol);
  control::CutPath path;
  const PathStreamFitter::Sink sink = [&](const StreamedSegment& s) {
    if (path.segments.empty()) path.start = s.from;
    path.segments.push_back(s.cmd);
    out.pieces.push_back(s.piece);
    out.piece_path.push_back(p);
    return true;
  };
  for (std::size_t k = b; k < e; ++k)
    if (!window.push(in.points[k], k < in.point_lines.size() ? in.point_lines[k] : 0, sink, error, status)) return false;
  if (!window.end_path(sink, error, status)) return false;
  out.lines_for_arcs += window.stats().lines_for_arcs;
  out.job.forced_commits += window.stats().forced;
  if (path.segments.empty()) return true;  // the whole path is shorter than the grid
  out.job.paths.push_back(std::move(path));
  out.path_point.push_back(b);
  return true;
}

}  // namespace

bool fit_paths(const io::PointFile& in, job::Criterion criterion, double tol, double feed_mm_s,
               FittedJob& out, std::string& error, Status& status, job::Numeric numeric) {
  out = FittedJob{};
  std::vector<std::size_t> begins = in.path_begin;
  if (begins.empty()) begins.push_back(0);
  std::unique_ptr<PathStreamFitter> window;  // for paths longer than it
  for (std::size_t p = 0; p < begins.size(); ++p) {
    const std::size_t b = begins[p];
    const std::size_t e = p + 1 < begins.size() ? begins[p + 1] : in.points.size();
    if (streams(in, b, e, criterion, numeric)) {
      if (!window) window = std::make_unique<PathStreamFitter>();
      if (!fit_in_window(in, p, b, e, criterion, tol, feed_mm_s, *window, out, error, status)) return false;
      continue;
    }
    const std::vector<Vec2<double>> pts(in.points.begin() + static_cast<std::ptrdiff_t>(b),
                                        in.points.begin() + static_cast<std::ptrdiff_t>(e));
    std::vector<double> tols;
    if (!in.tols.empty())
      tols.assign(in.tols.begin() + static_cast<std::ptrdiff_t>(b), in.tols.begin() + static_cast<std::ptrdiff_t>(e));
    std::vector<fit::Piece<double>> pieces;
    std::string why;
    if (!job::fit_job(pts, tols, tol, criterion, pieces, why, status, numeric)) {
      error = "path " + std::to_string(p + 1) + " (line " +
              std::to_string(b < in.point_lines.size() ? in.point_lines[b] : 0) + "): " + why;
      return false;
    }
    control::CutPath path;
    if (!motion::snap_to_grid(pts.front(), kLinkGrid, path.start)) {
      error = "path " + std::to_string(p + 1) + ": its start lies beyond the link's coordinate range";
      status = Status::invalid_argument;
      return false;
    }
    // Each piece as the segments the board runs (motion/segment_contract.hpp):
    // on the link's grid, starting where the previous one ends.
    Vec2<double> from = path.start;
    for (const fit::Piece<double>& piece : pieces) {
      const motion::Emitted<double> em = motion::emit_on_grid(from, piece.segment, kLinkGrid);
      if (em.status != motion::EmitStatus::ok) {
        error = "path " + std::to_string(p + 1) + " (line " +
                std::to_string(piece.first + b < in.point_lines.size() ? in.point_lines[piece.first + b] : 0) +
                "): " +
                (em.status == motion::EmitStatus::off_grid ? "a point beyond the link's coordinate range"
                                                           : "internal error: the fit made a segment no board runs");
        status = Status::invalid_argument;
        return false;
      }
      for (int k = 0; k < em.count; ++k) {
        const Segment<double>& g = em.segments[k];
        hal::SegmentCommand c;
        c.kind = g.kind;
        c.end = g.end;
        c.centre = g.centre;
        c.dir = g.dir;
        c.feed = feed_mm_s;
        c.torch = true;
        path.segments.push_back(c);
        fit::Piece<double> run = piece;
        run.segment = g;
        out.pieces.push_back(run);
        out.piece_path.push_back(p);
        from = g.end;
      }
      out.lines_for_arcs += static_cast<std::size_t>(em.lines_for_arcs);
    }
    if (path.segments.empty()) continue;  // the whole path is shorter than the grid
    out.job.paths.push_back(std::move(path));
    out.path_point.push_back(b);
  }
  if (out.job.paths.empty()) {
    error = "every path is shorter than the link's resolution (0.001 mm)";
    status = Status::invalid_argument;
    return false;
  }
  status = Status::ok;
  return true;
}

int fit_paths_or_say(const io::PointFile& in, job::Criterion criterion, double tol, double feed_mm_s,
                     FittedJob& out, job::Numeric numeric, const config::CutRules* rules) {
  std::string error;
  Status status = Status::ok;
  if (fit_paths(in, criterion, tol, feed_mm_s, out, error, status, numeric)) {
    if (rules) {
      out.cut_rules = apply_cut_rules(out, *rules);
      say_cut_rules(in.file, out.cut_rules, *rules);
    }
    return 0;
  }
  std::fprintf(stderr, "kerf: %s: %s\n", in.file.c_str(), error.c_str());
  return status == Status::invalid_argument || status == Status::degenerate ? 2 : 1;
}

bool open_journal(const std::string& path, bool resume, const control::Job& job,
                  std::unique_ptr<control::Journal>& out, control::ResumePoint& from) {
  control::WholeJobSource source(job);
  return open_journal(path, resume, source, out, from);
}

bool open_journal(const std::string& path, bool resume, JobSource& job, std::unique_ptr<control::Journal>& out,
                  control::ResumePoint& from) {
  from = control::ResumePoint{};
  from.from = job.locate(0).start;
  out.reset();
  if (path.empty()) return true;
  std::string error;
  out = resume ? control::Journal::resume(path, job.id(), error) : control::Journal::create(path, job.id(), error);
  if (!out) {
    std::fprintf(stderr, "kerf: --journal: %s\n", error.c_str());
    return false;
  }
  if (resume) from = control::resume_point(job, out->state());
  return true;
}

}  // namespace kerf::control
