// Welding a G-code file: each XY polyline of G1 moves becomes the fewest
// G2/G3 arcs (and G1 lines) the chosen criterion allows within tol; every
// other line is written back byte for byte.
//
// Rounding rule: a piece is fitted at tol minus a rounding budget of
// 2 * 10^-D (file units), written with D decimals (I/J relative to the
// rounded start), then measured as a controller will run it: the drawn arc
// around the rounded centre, widened by the difference between its start
// and end radius. The measure is the largest of: each input point inside the
// piece to the drawn arc, sample points of the arc (tol/4 apart, at most 512
// of them) to the input polyline, and the moved end point to its input point.
// The band criterion's arcs are inside the band by construction (the fitter
// certifies it); for the vertex criterion, the samples are the band check. Over tol, the piece is written again with D+1 and D+2
// decimals; still over tol, its input lines are kept as they were.
#pragma once

#include <cstddef>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>

#include "job/criterion.hpp"
#include "job/gcode_reader.hpp"

namespace kerf::weld {

struct WeldOptions {
  double tol_mm = 0.025;
  job::Criterion criterion = job::Criterion::band;  // vertex or band
  int decimals = -1;               // < 0: as many as the file's X/Y words use (at least 3)
  bool split_turns = true;         // fit separately at turns sharper than 90 degrees
  double jitter = 0.02;            // fit without points within jitter * tol of their chord (0: keep all)
  // The fitters' tie-break precision (fit/fit.hpp), per criterion; it does
  // not change the piece count, only how far under tol the pieces stay.
  // < 0: weld's choice (tie_break_for); 0: the fitters' own; >= 1: none.
  double tie_break = -1;
  // Threads that plan the parts of the polylines (split at sharp turns, each
  // planned apart): 0 one per core, else at most this many and the cores; 1
  // plans on the calling thread. The output is the same, byte for byte, for
  // any count.
  int threads = 0;
  // As runs are fitted, in file order, always from the calling thread, with
  // the (1-based) source line reached; may be empty.
  std::function<void(std::size_t line)> progress;
};

struct WeldStats {
  std::size_t input_moves = 0;   // blocks that move (G0..G3)
  std::size_t output_moves = 0;
  std::size_t arcs = 0;          // G2/G3 written by weld
  std::size_t polylines = 0;     // welded
  std::size_t kept_pieces = 0;   // pieces left as their input lines (rounding)
  double max_deviation_mm = 0;   // measured, over the written pieces
  int decimals = 0;
  std::size_t lines = 0;          // read (streaming; weld_gcode leaves it 0)
  std::size_t forced_commits = 0;  // polylines cut at the window's end (streaming)
};

// The tie-break precision weld uses for `criterion` (opts.tie_break < 0).
double tie_break_for(job::Criterion criterion);

// The threads weld_gcode plans on for opts.threads == requested.
unsigned weld_threads(int requested);

namespace detail {
struct Writer;
}

// Welds a file part by part, in order: each call writes blocks [0, end) of
// one part to `out` (appended), with the writing state (the modal arc, the
// rounding offset) carried from part to part. Every polyline of the part
// that starts before `end` must end before it. With D = `decimals`.
class Welder {
 public:
  Welder(const WeldOptions& opts, int decimals, WeldStats& stats, std::string& out);
  ~Welder();
  Welder(const Welder&) = delete;
  Welder& operator=(const Welder&) = delete;
  // False with "FILE:LINE: reason" when a fit fails; nothing of g is then to be written.
  bool add(const job::GcodeFile& g, std::size_t end, std::string& error);
  // The decimals of the parts from now on (streaming stdin: they grow as they are seen).
  void set_decimals(int decimals) { stats_.decimals = decimals; }

 private:
  const WeldOptions& opts_;
  WeldStats& stats_;
  std::unique_ptr<detail::Writer> writer_;
};

// Welds g, read whole, into `out` (the oracle of the streaming weld). False with `error` when a fit fails (a bug or a numeric
// breakdown): then nothing is to be written.
bool weld_gcode(const job::GcodeFile& g, const WeldOptions& opts, std::string& out,
                WeldStats& stats, std::string& error);

// Streaming (weld/weld_stream.cpp): the file is read `chunk_bytes` at a
// time, in whole lines; a polyline still open at a part's end is read again
// with the next part, unless it already spans more than `window_lines`
// lines: then it is cut there (a forced commit, counted) and the next part
// starts another polyline from its end point. Memory stays about that of one
// part and a window. Without forced commits the output is the same, byte for
// byte, as weld_gcode's on the whole file, given the same decimals: when
// opts.decimals < 0 they are the most seen so far (at least 3), so give the
// file's own (scan_gcode) when the input can be read twice.
struct StreamOptions {
  std::size_t chunk_bytes = std::size_t{1} << 20;
  std::size_t window_lines = std::size_t{1} << 16;
};

// Takes each piece of output in order; false when it cannot be written.
using Sink = std::function<bool(const std::string&)>;

// `error` is "FILE:LINE: reason" (or "FILE: reason") unless ok.
enum class StreamEnd { ok, bad_input, fit_failed, write_failed };
StreamEnd weld_stream(std::FILE* in, const std::string& name, const Sink& sink, const WeldOptions& opts,
                      const StreamOptions& so, WeldStats& stats, std::string& error);

// What a first pass over a file finds: its X/Y decimals and lines (parsed
// part by part, so a bad line is refused before anything is written).
struct GcodeScan {
  std::size_t decimals = 0;
  std::size_t lines = 0;
};
bool scan_gcode(std::FILE* in, const std::string& name, std::size_t chunk_bytes, GcodeScan& scan,
                std::string& error);

// `kerf weld` once its options are checked (app/weld_command.cpp): reads
// `in` ("-": stdin), welds it, writes `out` ("-": stdout) and the summary
// (on stderr when the G-code goes to stdout), with progress on a terminal.
// Returns the exit code (io/options.hpp).
int weld_file(const std::string& in, const std::string& out, WeldOptions w);

}  // namespace kerf::weld
