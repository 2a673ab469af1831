// One cut path fitted in a bounded window, its segments handed on as soon
// as they are decided (the streaming job pipeline, control/README.md).
//
// The points come one by one. While the path fits in the window they are
// only held; at the path's end it is fitted whole, by fit_paths itself, so
// the segments are byte for byte the whole-file ones. A path longer than
// the window goes through the core's streaming fit (fit/stream.hpp,
// vertex or band criterion, double): the held points first, then each new
// one; a piece is emitted when decided, on the link's grid, after the same
// check fit_paths' fit passes (a piece that fails it is fitted again in
// halves, as job/fit_job.hpp does). Where the window forces a commit the pieces
// stay within tol (each one is checked) and only their count may exceed the
// minimum; stats().forced counts them for the run report. With no forced
// commit the streamed pieces are the whole path's without the tie-break
// (fit/stream.hpp, "Exactness"). Memory: the window's points, whatever the
// path's length. Other criteria and --numeric fixed hold the whole path.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "control/fit_paths.hpp"
#include "kerf/fit/stream.hpp"
#include "kerf/fit/stream_band.hpp"

namespace kerf::control {

// A segment as the board runs it, with the piece it comes from (its point
// indices counted from the path's first point).
struct StreamedSegment {
  hal::SegmentCommand cmd;
  fit::Piece<double> piece;
  Vec2<double> from{};  // where it starts: the pierce point for a path's first
};

struct PathStreamStats {
  std::uint64_t points = 0;    // points pushed (all paths)
  std::uint64_t segments = 0;  // segments emitted
  std::uint32_t forced = 0;    // forced commits (paths longer than the window)
  std::uint32_t streamed_paths = 0;  // paths longer than the window
  std::size_t lines_for_arcs = 0;    // arcs too small for the grid, run as chords
};

class PathStreamFitter {
 public:
  static constexpr std::uint32_t kMaxWindow = 4096;
  // The segment sink: false stops the fit (the consumer is gone).
  using Sink = std::function<bool(const StreamedSegment&)>;

  PathStreamFitter();
  ~PathStreamFitter();
  // window: the points a path may hold (16 .. kMaxWindow). Allocates here
  // only. False with `error` for a window out of range.
  bool start(job::Criterion criterion, job::Numeric numeric, double feed_mm_s, std::uint32_t window,
             std::string& error);
  // A new path at tolerance tol (> 0). `file` names it in errors.
  void begin_path(const std::string& file, std::size_t path_index, double tol);
  // The next point, read at `line`. False with "path N (line L): reason".
  bool push(Vec2<double> p, std::size_t line, const Sink& sink, std::string& error, Status& status);
  // The path's end: its last segments. False as push. A path shorter than a
  // grid count emits nothing (segments_in_path() == 0) and is no error.
  bool end_path(const Sink& sink, std::string& error, Status& status);
  std::size_t segments_in_path() const { return path_segments_; }
  const PathStreamStats& stats() const { return stats_; }

 private:
  using Vertex = fit::PointWindow<double, kMaxWindow>;
  using Band = fit::BandWindow<double, kMaxWindow>;
  bool go_streaming(const Sink& sink, std::string& error, Status& status);
  bool stream_point(Vec2<double> p, std::size_t line, const Sink& sink, std::string& error, Status& status);
  bool emit_piece(const fit::Piece<double>& piece, const Sink& sink);
  bool emit_checked(const fit::Piece<double>& piece, const Sink& sink);
  std::string where(std::uint64_t point) const;

  job::Criterion criterion_ = job::Criterion::vertex;
  job::Numeric numeric_ = job::Numeric::floating;
  double feed_ = 0, tol_ = 0;
  std::uint32_t window_ = 0;
  std::string file_;
  std::size_t path_ = 0, path_segments_ = 0;
  std::vector<Vec2<double>> held_;         // the path's points while it fits the window
  std::vector<std::size_t> held_lines_;
  bool streaming_ = false, sink_stopped_ = false;
  std::string piece_error_;
  Status piece_status_ = Status::ok;
  std::unique_ptr<Vertex> vertex_;
  std::unique_ptr<Band> band_;
  // Streaming: accepted point k at k % recent_.size() (the window and more),
  // for each piece's check and the lines in errors.
  std::vector<Vec2<double>> recent_;
  std::vector<std::size_t> recent_lines_;
  std::vector<Vec2<double>> span_;
  std::uint64_t accepted_ = 0;
  Vec2<double> from_{};  // where the next segment starts (on the grid)
  PathStreamStats stats_;
};

}  // namespace kerf::control
