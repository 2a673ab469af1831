// The run plot: one self-contained SVG (no script, no external font) of a
// simulated or real run, written by `kerf sim`.
//
// Top panel: the XY view at equal scale, y up. Input points as small dots,
// each fitted piece as its own <path class="piece"> (arcs as SVG `A`
// commands, lines as `L`; colours cycle a palette), the band's half-width
// `tol` in the legend, the executed trace as polylines split into torch-on
// runs (class "cut", solid, dark) and torch-off runs (class "rapid", dashed,
// grey), each pierce (torch off -> on) as a red ring, and the table's
// outline (the soft limits) when given.
// Bottom panel: the speed over time, from consecutive trace samples, in
// mm/min, with the torch-on intervals shaded.
//
// Size: each trace polyline is decimated to at most kMaxPolylineVertices
// vertices. The run is cut into buckets, and each bucket keeps its first and
// last samples and those of its smallest and largest x and y (the speed curve:
// its slowest and fastest), in order, so corners and peaks survive.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kerf/geom/segment.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::io {

inline constexpr std::size_t kMaxPolylineVertices = 4000;

// One executed servo sample; the same fields as sim::TraceSample, defined here
// so that kerf_io builds where kerf_sim (libmodbus) does not.
struct TraceSample {
  double t_s = 0.0;
  Vec2<double> pos{};  // mm
  std::uint32_t seq = 0;  // segment being executed, 0 when idle
  bool torch = false;
};

// A program action at rest drawn on the XY panel: a dwell (class "dwell",
// a blue square) or a pause (class "pause", an orange diamond), with its
// text as the mark's <title>.
struct PlotMark {
  Vec2<double> at{};
  std::string kind;  // "dwell" or "pause"
  std::string text;
};

struct RunPlot {
  std::vector<std::vector<Vec2<double>>> paths;  // input points, per path
  std::vector<Segment<double>> pieces;           // fitted pieces, in job order
  std::vector<std::size_t> piece_path;           // path index of each piece
  double tol = 0;                                // band half-width, mm
  std::vector<TraceSample> trace;
  std::vector<PlotMark> marks;                   // dwells and pauses
  bool table = false;                            // the table's outline (the soft limits; class "table")
  Vec2<double> table_lo{}, table_hi{};
  std::string title;
};

std::string format_run_svg(const RunPlot& plot);

}  // namespace kerf::io
