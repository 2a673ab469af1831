// Reading a G-code file into blocks (one per source line) and the XY
// polylines that `kerf weld` may replace with arcs.
//
// Supported: G0/G1/G2/G3 (I J or R arcs), G4, G17/G18/G19, G20/G21, G90/G91,
// G92, F, S, T, P, N line numbers, `$n` (a spindle select, as an unknown word), `;` and `( )` comments, M3/M4/M5 (torch),
// M7/M8/M9, M0/M1/M2/M30. Dialects: zero-padded words (G01, M03), bare modal
// lines (X.. Y.. with no G word), blanks and tabs anywhere, lower case, LF,
// CRLF or CR CR LF line ends (a file with an LF ends its lines there; one
// without, at CR), inch files (G20), a `%` tape mark.
//
// A line with a parameter (#), an expression ([...]) or an O-word is marked
// `dynamic`: job/gcode_expr.hpp parses it (its syntax errors are refused
// here) and job/gcode_flow.hpp runs it. Weld never replaces it, and after
// the first O-word no line is welded (a loop or a call may run it again).
// Refused with a file:line reason: block delete (/), malformed words, a G or
// M code given by an expression. Anything else it does not model (other G or M codes,
// axis letters A B C E U V W, ...) is an "unknown word": kept on the block so
// that `kerf weld` passes the line through and `kerf run` refuses it.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/geom/vec2.hpp"
#include "io/point_file.hpp"

namespace kerf::job {

inline constexpr double kMmPerInch = 25.4;

// A G or M word's code in tenths (M3: 30, G38.2: 382), compared exactly.
inline int code10(double v) { return static_cast<int>(std::lround(v * 10.0)); }

enum class Motion : std::uint8_t { none, rapid, linear, cw, ccw };

// 16 bytes: a large file has hundreds of thousands of words, each written
// to memory touched for the first time.
struct GWord {
  double value = 0.0;
  std::uint32_t pos = 0;      // where the word starts in GBlock::text (lines are at most 64 KiB)
  std::uint32_t len : 24 = 0;  // its length as written (blanks inside included)
  char letter : 8 = 0;        // upper case
};

struct GBlock {
  std::size_t line = 0;        // 1-based source line
  // The views and spans below point into GcodeFile::source: one buffer each
  // for the whole file instead of several allocations per line.
  std::string_view text;       // the line as read, without its line end
  std::string_view end;        // its line end as read: "\n", "\r\n", "\r" or "" (last line)
  std::span<const GWord> words;
  std::span<const std::string_view> comments;  // each comment as written, delimiters included
  std::span<const std::string_view> unknown;   // words kerf does not model, as written
  Motion motion = Motion::none;  // modal motion in force after this block
  bool motion_word = false;    // the block names its motion (G0..G3)
  bool moves = false;          // it programs a motion (axis words under a motion mode)
  bool xy_plane = true;        // G17 in force
  bool inches = false;         // G20 in force
  bool relative = false;       // G91 in force
  bool torch = false;          // M3/M4 in force after this block
  bool known_start = false;    // the XY position before the block is known
  double start[3] = {0, 0, 0};  // position before the block (file units)
  double end_pos[3] = {0, 0, 0};  // position after it
  double centre[2] = {0, 0};   // arc centre, absolute (G2/G3 moves only)
  bool has_f = false;
  bool new_feed = false;       // an F word that changes the feed in force (a repeated one is modal noise)
  bool dynamic = false;        // parameters, expressions or an O-word: words is empty, the text is parsed at run
  bool only_comment() const { return words.empty() && !dynamic; }
  // A G1 move in the XY plane with only X, Y (and N, F, G1) words, and Z
  // only to repeat the known Z: a polyline vertex that welding may replace.
  bool xy_line = false;
  std::size_t decimals = 0;    // most digits after the point in its X/Y words
};

// A run of consecutive xy_line blocks (comment-only lines in between do not
// break it; an F that changes the feed starts another) at a known start.
// points[0] is the start; points[k] (k >= 1) is
// the end of block point_block[k].
struct GPolyline {
  std::size_t first_block = 0;  // index in GcodeFile::blocks
  std::size_t last_block = 0;   // inclusive
  std::vector<Vec2<double>> points;
  std::vector<std::size_t> point_block;  // point_block[0] is unused (the start)
  bool inches = false;
  bool relative = false;
};

struct GcodeFile {
  bool ok = false;
  std::string file;
  // What the blocks' views and spans point into (shared, so that copies of
  // the file stay valid).
  struct Source {
    std::string text;                        // the file as read
    std::vector<GWord> words;                // every block's words, in order
    std::vector<std::string_view> pieces;    // every block's comments, then its unknown words
  };
  std::shared_ptr<const Source> source;
  std::size_t line = 0;  // of the error
  std::string reason;
  std::vector<GBlock> blocks;
  std::vector<GPolyline> polylines;
  std::size_t decimals = 0;  // most digits after the point in any X/Y word
};

// The modal state between two lines: what reading a file in parts carries
// from one part to the next (kerf weld streams, weld/weld_stream.cpp).
struct GcodeModal {
  Motion motion = Motion::none;
  bool xy_plane = true;
  bool inches = false;
  bool relative = false;
  bool torch = false;
  double pos[3] = {0, 0, 0};
  bool known[3] = {false, false, false};
  bool flow = false;  // an O-word was read: a loop or a call may run any later line again
  double feed = std::nan("");  // the F in force (NaN: none yet)
  bool lf_ends = true;  // the file's lines end at LF (else CR only); set by the first part with a line end
  bool ends_known = false;
};

// One part of a file, parsed as its lines from `first_line` on: `modal` is
// the state before them, and after them once parsed. `run_block` is the
// first block of the run (a GPolyline) still open at the part's end, or npos,
// and `at_run` the state before it: where to read again from to keep that run whole.
struct GcodePart {
  GcodeModal modal;
  std::size_t first_line = 1;
  std::size_t run_block = static_cast<std::size_t>(-1);
  GcodeModal at_run;
};
GcodeFile parse_gcode_part(std::string text, std::string display_name, GcodePart& part);

// Reads `path` ("-": stdin) and parses it.
GcodeFile read_gcode(const std::string& path);
GcodeFile parse_gcode(std::string_view text, std::string display_name);

// "FILE:LINE: reason".
std::string describe_error(const GcodeFile& f);
// "FILE:LINE: ", the start of a reason.
inline std::string where(const std::string& file, std::size_t line) {
  std::string s = file;
  s += ':';
  s += std::to_string(line);
  s += ": ";
  return s;
}

// A G-code job as cut paths for `kerf sim` / `kerf run`: the XY points of the
// moves made with the torch on (every feed move when the file never uses M3/M4),
// split into paths at rapids and at torch-off; arcs are sampled into points
// (chord error below 0.001 mm). Coordinates in mm. Unknown words are refused.
// False with "FILE:LINE: reason" in error. (job/gcode_job.cpp)
bool read_gcode_job(const std::string& path, io::PointFile& out, std::string& error);

// True for the usual G-code extensions (.nc .ngc .gcode .gco .gc .tap .cnc),
// in any case: how `kerf sim`/`kerf run` can tell a G-code job from a point file.
bool is_gcode_path(const std::string& path);
bool gcode_job_from(const GcodeFile& g, io::PointFile& out, std::string& error);

}  // namespace kerf::job
