// What `kerf sim --plot` draws besides the trace, kept within a budget so
// that a long job's plot does not hold the job: the input points (at most
// kPlotPoints) and the fitted pieces the controller pulled (at most
// kPlotPieces, job_watch.hpp hands them over as it reads them). A job
// within the budget is drawn whole, as before; past it the title says how
// much of the job the dots and pieces show (the trace, thinned by
// trace_recorder.hpp, is always the whole run). Nothing is kept when no
// plot is asked for. An SVG of a million pieces would not open anyway.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "io/run_svg.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf::simulated {

inline constexpr std::size_t kPlotPoints = std::size_t{1} << 17;
inline constexpr std::size_t kPlotPieces = std::size_t{1} << 16;

class PlotKeeper {
 public:
  explicit PlotKeeper(bool on, std::size_t max_points = kPlotPoints, std::size_t max_pieces = kPlotPieces);
  bool on() const { return on_; }
  // Path p's input points (paths in order); false once the budget is full.
  bool add_points(std::size_t path, const Vec2<double>* points, std::size_t n);
  void add_piece(const Segment<double>& s, std::size_t path);
  // The plot's paths, pieces and title; trace, tol and marks are the caller's.
  io::RunPlot take(const std::string& title);

 private:
  bool on_;
  std::size_t max_points_, max_pieces_;
  std::size_t points_ = 0, points_left_out_ = 0, pieces_left_out_ = 0;
  io::RunPlot plot_;
};

}  // namespace kerf::simulated
