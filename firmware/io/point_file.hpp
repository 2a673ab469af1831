// Reading the ordered points of a cut path from a text file or stdin.
//
// One "x y" pair per line, the two numbers separated by spaces, tabs or one
// comma (with optional blanks around it). A third column, on every line or
// none, is that point's own tolerance (> 0), for the band criterion; or,
// when the caller asks for angles, the point's tangent direction in degrees
// (the biarc criterion's `--tangent-format angle`). Four columns `x y tx ty`
// give the tangent as a vector (not zero; it is normalised). '#' starts a comment that runs to
// the end of the line; CRLF line ends are accepted.
//
// A job may hold several cut paths: one or more blank lines (empty or only
// blanks) separate them. A line holding only a comment is not blank and does
// not separate. Blank lines before the first or after the last point make no
// empty path. Each path needs at least two distinct points.
//
// Consecutive duplicate points within a path are dropped and counted; a path's
// first point equal to the previous path's last is kept (it is a new pierce).
//
// Errors are values: nothing here throws across the API (an allocation
// failure is the one exception, std::bad_alloc, which the caller handles).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/geom/vec2.hpp"

namespace kerf::io {

// Coordinates beyond this magnitude are refused: far past any machine (1e15 mm
// is a million km), so such a file is a unit or format mistake.
inline constexpr double kMaxCoordinate = 1e15;

// A line longer than this is refused (a point line is a few dozen bytes): a
// binary or runaway file is reported at once, not read whole into memory.
inline constexpr std::size_t kMaxLineBytes = 65536;

struct PointFile {
  bool ok = false;
  std::string file;          // display name: the path, or "<stdin>" for "-"
  std::size_t line = 0;      // 1-based line of the error; 0 for the file as a whole
  std::string reason;        // why it failed, e.g. `not a number: "abc"`
  std::vector<Vec2<double>> points;       // after dropping consecutive duplicates
  std::vector<std::size_t> point_lines;   // the source line of each kept point
  std::vector<double> tols;               // each kept point's tol: empty unless 3 columns
  std::vector<Vec2<double>> tangents;     // each kept point's unit tangent: empty unless
                                          // 4 columns, or 3 read as angles
  std::vector<std::size_t> path_begin;    // index in points of each path's first point
  std::size_t duplicates_dropped = 0;
};

// Reads `path`, or stdin when path is "-". third_is_angle: a third column is
// a tangent angle in degrees, not a tol.
PointFile read_points(const std::string& path, bool third_is_angle = false);

// Parses the text of a point file; `display_name` only labels errors.
PointFile parse_points(std::string_view text, std::string display_name,
                       bool third_is_angle = false);

// "FILE:LINE: reason", or "FILE: reason" for an error about the whole file.
std::string describe_error(const PointFile& f);

}  // namespace kerf::io
