// A G-code program read as a stream (issue 24): its paths and actions one at
// a time, in program order, so that `kerf sim` and `kerf run` can fit and cut
// the first path before the file has been read to its end. Each item is what
// read_gcode_program (job/gcode_program.hpp) would give for the same file:
// the same points, lines, feeds, path settings and actions.
//
// WholeProgramStream walks a GcodeProgram held in memory: the oracle the
// streamed reading is compared against, and the fallback for what cannot be
// read in a window. open_program_stream picks the reading for a file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "job/gcode_program.hpp"

namespace kerf::job {

// One program path with its points (GcodeProgram::points between two
// path_begin entries, and the matching point_feed).
struct ProgramPiece {
  ProgramPath path;
  std::vector<Vec2<double>> points;  // machine mm
  std::vector<std::size_t> lines;    // each point's source line
  std::vector<double> feed;          // each point's feed, mm/min (0: the configuration's cut feed)
};

class ProgramStream {
 public:
  enum class Next : std::uint8_t { path, action, end, error };
  virtual ~ProgramStream() = default;
  // The next item in program order: a path (into `path`) or an action (into
  // `action`, before_path counting the paths given before it). After `end`,
  // summary() is complete; after `error`, error() says why.
  virtual Next next(ProgramPiece& path, ProgramAction& action) = 0;
  // "FILE:LINE: reason".
  virtual const std::string& error() const = 0;
  // The file has no torch word: every path is a dry run. Known before the first next().
  virtual bool dry_run() const = 0;
  // The program's facts beyond its paths and actions (interp's constructs,
  // notes, analog inputs, final state; z_moves, final_z, dry_run; points.file).
  // Its points, point_feed, paths and actions stay empty. Complete after `end`.
  virtual const GcodeProgram& summary() const = 0;
};

class WholeProgramStream final : public ProgramStream {
 public:
  explicit WholeProgramStream(GcodeProgram program);
  Next next(ProgramPiece& path, ProgramAction& action) override;
  const std::string& error() const override { return error_; }
  bool dry_run() const override { return program_.dry_run; }
  const GcodeProgram& summary() const override { return summary_; }

 private:
  GcodeProgram program_;
  GcodeProgram summary_;
  std::size_t path_ = 0, action_ = 0;
  std::string error_;
};

// How open_program_stream reads a file (job/program_window.hpp).
struct ProgramStreamOptions {
  std::size_t part_bytes = std::size_t{256} << 10;  // read at a time by the window reading
  bool whole = false;  // read the file whole (the oracle): WholeProgramStream
};

// The stream of a G-code file: false with "FILE:LINE: reason" for what
// read_gcode_program refuses before its first path. A file is read in a
// window (job/program_window.hpp) unless it is no regular file (stdin "-",
// a pipe: it cannot be read twice), it has O-words
// (the flow jumps), or its torch word is computed: those are read whole.
// The window reading refuses at open what read_gcode refuses (a line that
// does not parse, anywhere in the file); what the interpreter refuses, and
// "no cut moves", come as Next::error when the stream reaches them.
// The stream is used by one thread at a time; it owns its file and copies
// of the settings and the state.
bool open_program_stream(const std::string& file, const InterpSettings& settings, const MachineState& state,
                         std::unique_ptr<ProgramStream>& out, std::string& error);
bool open_program_stream(const std::string& file, const InterpSettings& settings, const MachineState& state,
                         const ProgramStreamOptions& options, std::unique_ptr<ProgramStream>& out,
                         std::string& error);

}  // namespace kerf::job
