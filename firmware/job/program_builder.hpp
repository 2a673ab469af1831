// Canonical moves (job/gcode_interp.hpp) built into a program's paths and
// actions (job/gcode_program.hpp), one at a time: build_program runs it on
// a whole interpretation, the window reading (job/program_window.hpp) on
// each block's moves as the file is read, taking each path out of `out`
// once it is final.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "job/gcode_program.hpp"
#include "job/program_stream.hpp"

namespace kerf::job {

class ProgramBuilder {
 public:
  // `out` receives the points, paths and actions (its other fields are
  // left as they are); dry_run: the file has no torch word.
  ProgramBuilder(bool z_axis, bool dry_run, const double start[2], GcodeProgram& out);

  void step(const Canon& c);
  // After the last canonical move: closes the open path, gives the moves
  // after the last path to it, sets out.final_z and records the z axis's
  // constructs in `constructs`.
  void finish(std::map<std::string, Construct>& constructs);

  // The window: paths taken out so far (an action's before_path counts them).
  std::size_t paths_taken() const { return taken_; }
  // out.paths[0] is final: no later move can join its `after` moves.
  bool first_path_final() const;
  // Moves out.paths[0] with its points into `piece` (final only).
  void take_first_path(ProgramPiece& piece);

 private:
  void close();
  void push_xy(Vec2<double> to, std::size_t line);
  void push_z(double z, double feed_mm_min, std::size_t line);
  void add(Vec2<double> q, std::size_t line, double feed);
  void action(const Canon& c);
  void move(const Canon& c);

  GcodeProgram& out_;
  Vec2<double> pos_{};
  double z_ = 0;
  bool z_axis_ = false;
  bool dry_run_ = false;
  bool finished_ = false;
  std::vector<ProgramMove> pending_;  // z axis: moves since the last path
  bool after_path_ = false;           // no action since the last path closed
  std::size_t ramps_ = 0, first_ramp_line_ = 0, first_z_line_ = 0;
  bool torch_ = false, open_ = false;
  double percent_ = 100, tol_ = 0, pierce_ = -1;
  std::size_t path_start_ = 0;
  std::size_t taken_ = 0;
  ProgramPath cur_;
  std::vector<Vec2<double>> arc_;
};

}  // namespace kerf::job
