#include "control/path_stream.hpp"

#include "job/check_fit.hpp"
#include "job/fit_job.hpp"

namespace kerf::control {

PathStreamFitter::PathStreamFitter() = default;
PathStreamFitter::~PathStreamFitter() = default;

bool PathStreamFitter::start(job::Criterion criterion, job::Numeric numeric, double feed_mm_s,
                             std::uint32_t window, std::string& error) {
  if (window < 16 || window > kMaxWindow) {
    error = "the fit window: expected 16 to " + std::to_string(kMaxWindow) + " points, got " + std::to_string(window);
    return false;
  }
  criterion_ = criterion;
  numeric_ = numeric;
  feed_ = feed_mm_s;
  window_ = window;
  stats_ = PathStreamStats{};
  held_.clear();
  held_.reserve(window);
  held_lines_.clear();
  held_lines_.reserve(window);
  // Streaming needs the core's window for the criterion, in double.
  if (numeric == job::Numeric::floating && criterion == job::Criterion::vertex && !vertex_) vertex_ = std::make_unique<Vertex>();
  if (numeric == job::Numeric::floating && criterion == job::Criterion::band && !band_) band_ = std::make_unique<Band>();
  recent_.assign(std::size_t{window} + 8, Vec2<double>{});
  recent_lines_.assign(recent_.size(), 0);
  span_.reserve(recent_.size());
  return true;
}

void PathStreamFitter::begin_path(const std::string& file, std::size_t path_index, double tol) {
  file_ = file;
  path_ = path_index;
  tol_ = tol;
  path_segments_ = 0;
  held_.clear();
  held_lines_.clear();
  streaming_ = sink_stopped_ = false;
  piece_error_.clear();
  piece_status_ = Status::ok;
  accepted_ = 0;
}

std::string PathStreamFitter::where(std::uint64_t point) const {
  const std::size_t line = point < accepted_ ? recent_lines_[point % recent_lines_.size()] : 0;
  return "path " + std::to_string(path_ + 1) + " (line " + std::to_string(line) + "): ";
}

bool PathStreamFitter::push(Vec2<double> p, std::size_t line, const Sink& sink, std::string& error, Status& status) {
  ++stats_.points;
  if (streaming_) return stream_point(p, line, sink, error, status);
  const bool can_stream = vertex_ && criterion_ == job::Criterion::vertex ? true
                          : band_ && criterion_ == job::Criterion::band;
  if (held_.size() < window_ || !can_stream || numeric_ != job::Numeric::floating) {
    held_.push_back(p);
    held_lines_.push_back(line);
    return true;
  }
  return go_streaming(sink, error, status) && stream_point(p, line, sink, error, status);
}

bool PathStreamFitter::go_streaming(const Sink& sink, std::string& error, Status& status) {
  streaming_ = true;
  ++stats_.streamed_paths;
  const Status s = criterion_ == job::Criterion::vertex ? vertex_->start(tol_, fit::Method::optimal, window_)
                                                        : band_->start(tol_, tol_, window_);
  if (s != Status::ok) {
    error = "path " + std::to_string(path_ + 1) + ": the streaming fit refused tol " + std::to_string(tol_);
    status = s;
    return false;
  }
  if (!motion::snap_to_grid(held_.front(), kLinkGrid, from_)) {
    error = "path " + std::to_string(path_ + 1) + ": its start lies beyond the link's coordinate range";
    status = Status::invalid_argument;
    return false;
  }
  for (std::size_t k = 0; k < held_.size(); ++k)
    if (!stream_point(held_[k], held_lines_[k], sink, error, status)) return false;
  held_.clear();
  held_lines_.clear();
  return true;
}

bool PathStreamFitter::stream_point(Vec2<double> p, std::size_t line, const Sink& sink, std::string& error,
                                    Status& status) {
  const std::size_t at = static_cast<std::size_t>(accepted_ % recent_.size());
  recent_[at] = p;  // before the push: the pieces it decides may end here
  recent_lines_[at] = line;
  auto on_piece = [&](const fit::Piece<double>& piece, bool) {
    if (piece_error_.empty() && !sink_stopped_) emit_piece(piece, sink);
  };
  const Status s = vertex_ && criterion_ == job::Criterion::vertex ? vertex_->push(p, on_piece)
                                                                   : band_->push(p, on_piece);
  if (s == Status::degenerate) return true;  // the same point again: nothing to fit
  if (s == Status::ok) ++accepted_;
  if (s != Status::ok || !piece_error_.empty()) {
    error = s != Status::ok ? "path " + std::to_string(path_ + 1) + " (line " + std::to_string(line) +
                                  "): fit failed: " + to_string(s)
                            : piece_error_;
    status = s != Status::ok ? s : piece_status_;
    return false;
  }
  return true;
}

bool PathStreamFitter::emit_piece(const fit::Piece<double>& piece, const Sink& sink) {
  span_.clear();
  for (std::uint64_t k = piece.first; k <= piece.last; ++k) span_.push_back(recent_[k % recent_.size()]);
  fit::Piece<double> local = piece;
  local.first = 0;
  local.last = piece.last - piece.first;
  const std::string bad = job::check_fit(Span<const Vec2<double>>(span_.data(), span_.size()),
                                         Span<const fit::Piece<double>>(&local, 1), tol_);
  if (bad.empty()) return emit_checked(piece, sink);
  // The fitters' blind spot (an arc round its points more than once):
  // the piece's points fitted again as fit_job does, in halves until each
  // passes the check. Within tol; only the count may grow.
  std::vector<fit::Piece<double>> again;
  std::string why;
  Status st = Status::ok;
  if (!job::fit_job(span_, {}, tol_, criterion_, again, why, st, numeric_)) {
    again.clear();  // last resort: a line from each point to the next, exact at the points
    for (std::size_t k = 0; k + 1 < span_.size(); ++k)
      again.push_back({static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(k + 1),
                       Segment<double>::line(span_[k], span_[k + 1]), 0.0});
  }
  for (fit::Piece<double> p : again) {
    p.first += piece.first;
    p.last += piece.first;
    if (!emit_checked(p, sink)) return false;
  }
  return true;
}

bool PathStreamFitter::emit_checked(const fit::Piece<double>& piece, const Sink& sink) {
  const motion::Emitted<double> em = motion::emit_on_grid(from_, piece.segment, kLinkGrid);
  if (em.status != motion::EmitStatus::ok) {
    piece_error_ = where(piece.first) + (em.status == motion::EmitStatus::off_grid
                                             ? "a point beyond the link's coordinate range"
                                             : "internal error: the fit made a segment no board runs");
    piece_status_ = Status::invalid_argument;
    return false;
  }
  stats_.lines_for_arcs += static_cast<std::size_t>(em.lines_for_arcs);
  for (int k = 0; k < em.count; ++k) {
    const Segment<double>& g = em.segments[k];
    StreamedSegment out;
    out.cmd.kind = g.kind;
    out.cmd.end = g.end;
    out.cmd.centre = g.centre;
    out.cmd.dir = g.dir;
    out.cmd.feed = feed_;
    out.cmd.torch = true;
    out.piece = piece;
    out.piece.segment = g;
    out.from = from_;
    from_ = g.end;
    ++path_segments_;
    ++stats_.segments;
    if (!sink(out)) {
      sink_stopped_ = true;
      return false;
    }
  }
  return true;
}

bool PathStreamFitter::end_path(const Sink& sink, std::string& error, Status& status) {
  if (streaming_) {
    auto on_piece = [&](const fit::Piece<double>& piece, bool) {
      if (piece_error_.empty() && !sink_stopped_) emit_piece(piece, sink);
    };
    const bool vertex = vertex_ && criterion_ == job::Criterion::vertex;
    const Status s = vertex ? vertex_->finish(on_piece) : band_->finish(on_piece);
    stats_.forced += vertex ? vertex_->stats().forced : band_->stats().forced;
    if (s != Status::ok || !piece_error_.empty()) {
      error = s != Status::ok ? "path " + std::to_string(path_ + 1) + ": fit failed: " + to_string(s) : piece_error_;
      status = s != Status::ok ? s : piece_status_;
      return false;
    }
    status = Status::ok;
    return true;
  }
  // The whole path: fit_paths itself, as the whole-file job fits it.
  io::PointFile one;
  one.file = file_;
  one.points = held_;
  one.point_lines = held_lines_;
  FittedJob f;
  if (!fit_paths(one, criterion_, tol_, feed_, f, error, status, numeric_)) {
    if (f.job.paths.empty() && status == Status::invalid_argument &&
        error.find("shorter than the link") != std::string::npos) {
      status = Status::ok;  // nothing to cut
      return true;
    }
    if (error.compare(0, 7, "path 1 ") == 0) error = "path " + std::to_string(path_ + 1) + error.substr(6);
    return false;
  }
  const CutPath& path = f.job.paths.front();
  stats_.lines_for_arcs += f.lines_for_arcs;
  for (std::size_t k = 0; k < path.segments.size(); ++k) {
    StreamedSegment out;
    out.cmd = path.segments[k];
    out.piece = f.pieces[k];
    out.from = k == 0 ? path.start : path.segments[k - 1].end;
    ++path_segments_;
    ++stats_.segments;
    if (!sink(out)) return true;  // the consumer is gone: nothing wrong here
  }
  status = Status::ok;
  return true;
}

}  // namespace kerf::control
