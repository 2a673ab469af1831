// The window reading of a G-code program (issue 24): the file is read in
// parts (job/gcode_part_reader.hpp), each part's blocks are run by the flow
// and the interpreter as they come (their state carries from part to part)
// and built into paths (job/program_builder.hpp); a path is given as soon as
// it is final, an action as soon as the paths before it are given.
//
// What it holds: the part being read (part_bytes of text, parsed), the
// parameters, offsets, constructs and notes, and the path being built: a
// path is held whole until it ends (with a z axis, until the next path ends
// or the program does: the moves after a path may still join it). Memory
// does not grow with the file's length.
//
// Before the first item, scan_program reads the file once without
// interpreting it: every line is parsed (so what read_gcode refuses is
// refused at open, with the same "FILE:LINE: reason"), and it finds
// - O-words: the flow jumps; open_program_stream then reads the file whole;
// - the torch word that makes the program no dry run (dry_run()): M3 or M4,
//   or M62/M64 P on InterpSettings::torch_output, on a line up to the first
//   M2/M30 (without O-words every line runs once, in order, up to it). An
//   M62/M64 whose P is computed, with a torch output configured, is known
//   only when it runs: that file too is read whole.
// What the interpreter refuses is met as the stream reaches it
// (Next::error, the text interpret gives); "no cut moves" at the end.
#pragma once

#include <cstddef>
#include <string>

#include "job/block_interp.hpp"
#include "job/gcode_flow.hpp"
#include "job/gcode_part_reader.hpp"
#include "job/program_builder.hpp"
#include "job/program_stream.hpp"

namespace kerf::job {

struct ProgramScan {
  bool o_words = false;        // an O-word line (the scan stops there)
  bool torch_word = false;     // the program is no dry run
  bool torch_unknown = false;  // an M62/M64 with a computed P and a torch output
};

// False with "FILE:LINE: reason" for a file read_gcode refuses.
bool scan_program(const std::string& file, const InterpSettings& settings, std::size_t part_bytes, ProgramScan& scan,
                  std::string& error);

class WindowProgramStream final : public ProgramStream {
 public:
  // dry_run: from scan_program.
  WindowProgramStream(const InterpSettings& settings, const MachineState& state, bool dry_run);
  // False with "FILE: reason" when the file cannot be opened.
  bool open(const std::string& file, std::size_t part_bytes, std::string& error);

  Next next(ProgramPiece& path, ProgramAction& action) override;
  const std::string& error() const override { return error_; }
  bool dry_run() const override { return dry_run_; }
  const GcodeProgram& summary() const override { return summary_; }

 private:
  enum class State : unsigned char { running, ended, failed };
  void advance();
  void finish();
  void fail(std::string why);

  InterpSettings settings_;
  bool dry_run_;
  GcodePartReader reader_;
  GcodeFile part_;
  Interpretation it_;  // its canon: the moves of the block being built
  BlockInterp interp_;
  GcodeFlow flow_;
  GcodeProgram window_;  // the paths not yet given, the actions not yet given
  ProgramBuilder builder_;
  GcodeProgram summary_;
  std::size_t canon_at_ = 0, action_at_ = 0;
  State state_ = State::running;
  std::string error_;
};

}  // namespace kerf::job
