// An independent reader of a G-code file's XY toolpath, for the tests. It
// shares no code with kerf's interpreter (firmware/job) or core: plain std
// C++, written from the LinuxCNC G-code reference, so that a mistake in the
// interpreter cannot hide in the check.
//
// Understood: G0 G1 G2 G3 (I J centre, or R), G90/G91, G90.1/G91.1, G20/G21,
// G17, work offsets G54..G59.3 set with G10 L2/L20, G92 (and G92.1, G92.2),
// G53 for one block, G28 (home: to the machine origin), M3/M4/M5 (torch),
// M2/M30 (end), N words, ( ) and ; comments, % lines, blanks anywhere.
// Z and feed do not change the XY path.
// Parameters, expressions and O-word flow are run first by its own
// evaluator (toolpath_eval.hpp).
// Refused with "LINE: reason": G30, G18/G19, G92.3, arcs whose end is off their circle by more than
// 0.01 mm + 1e-4 of the radius (LinuxCNC refuses these as well).
// Everything else (other G and M codes, T, S, F, P, E ...) does not move XY
// and is skipped. The machine starts at the origin of machine coordinates.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace kerf_test {

struct TPoint {
  double x = 0;
  double y = 0;
};

// One XY move in machine coordinates, mm.
struct TMove {
  bool rapid = false;  // G0
  bool arc = false;    // G2/G3
  int dir = 0;         // arcs: +1 counter-clockwise (G3), -1 clockwise (G2)
  TPoint start, end, centre;
  bool torch = false;  // M3/M4 in force
  bool z_moves = false;   // the block also moves Z (a helix, a ramp)
  bool after_z = false;   // Z moved on its own since the previous XY move
  std::size_t line = 0;
};

struct Toolpath {
  bool ok = false;
  std::string error;  // "LINE: reason"
  bool uses_torch = false;  // the file has an M3, M4 or M5
  std::vector<TMove> moves;  // every XY move, in order (zero-length ones dropped)
};

Toolpath read_toolpath(const std::string& path);
Toolpath parse_toolpath(const std::string& text);

// The moves a cut follows: the feed moves made with the torch on, or every
// feed move in a file with no torch word (a dry run follows them all).
std::vector<TMove> cut_moves(const Toolpath& t);

// Distance from p to a move (its own extent: a line segment, or an arc's sweep).
double distance_to_move(const TMove& m, TPoint p);

// Nearest-move queries over many moves: a uniform grid of buckets.
class MoveIndex {
 public:
  MoveIndex(std::vector<TMove> moves, double cell_mm);
  // The distance from p to the nearest move, exact when it is <= reach (only
  // buckets within reach are searched), otherwise from a search of them all.
  double nearest(TPoint p, double reach) const;
  std::size_t size() const { return moves_.size(); }

 private:
  long long key(long long i, long long j) const { return i * 2000003LL + j; }
  std::vector<TMove> moves_;
  double cell_;
  std::vector<std::size_t> big_;  // moves too large to bucket: always searched
  std::vector<std::pair<long long, std::size_t>> buckets_;  // (cell key, move), sorted
};

}  // namespace kerf_test
