// A G-code program (job/gcode_program.hpp) fitted into a controller Job:
// each path at its own tolerance (G64 P, capped by fit.tol), each segment at
// the slowest feed programmed along it (F or the material's, times the feed
// %, capped by the machine's max feed), torch on or dry run, with the
// program's actions between the paths.
#pragma once

#include <string>
#include <vector>

#include "control/fit_paths.hpp"
#include "control/run_report.hpp"
#include "job/gcode_program.hpp"

namespace kerf::control {

// What fits a program path (the configuration's fit and feeds).
struct PathFitSettings {
  job::Criterion criterion = job::Criterion::band;
  job::Numeric numeric = job::Numeric::floating;
  double tol = 0.025;            // mm; a path's G64 P may lower it
  double feed_mm_s = 50.0;       // the cut feed
  double max_feed_mm_s = 1e300;  // caps every feed
};

// One program path as the job cuts it, shared by the whole job
// (fit_program_or_say) and the streamed one (control/streamed_job.hpp):
// `one` holds its points and lines (and a point file's tols), `feed` each
// point's mm/min (0 or missing: the cut feed), p its number in the program.
// 0 with `out` holding one CutPath (segments at the slowest feed along each
// piece, the torch, the pierce delay, pp's moves before and after) and its
// pieces; none for a path shorter than the link's grid (its moves are the
// caller's to carry). Otherwise the exit code (2 bad input, 1 otherwise) and
// "path N (line L): reason".
int fit_program_path(const io::PointFile& one, const std::vector<double>& feed, const job::ProgramPath& pp,
                     std::size_t p, const PathFitSettings& s, FittedJob& out, std::string& error);

// A program's moves between paths (z axis) as link commands, on the grid.
void append_moves(const std::vector<job::ProgramMove>& moves, double max_feed_mm_s,
                  std::vector<hal::SegmentCommand>& out);

// On failure prints "kerf: FILE: reason" and returns the exit code (2 bad input, 1 otherwise); 0 on success.
// With `rules`, the cutting rules (control/cut_rules.hpp) then scale the feeds and add overcuts, as for a point file.
int fit_program_or_say(const job::GcodeProgram& prog, job::Criterion criterion, double tol, double feed_mm_s,
                       double max_feed_mm_s, FittedJob& out, job::Numeric numeric = job::Numeric::floating,
                       const config::CutRules* rules = nullptr);

// What kerf run's machine has for a program (the configuration's
// [[gpio.output]] and [[gpio.input]] numbers, [analog] ignore, [bench]).
struct MachineIo {
  std::vector<int> outputs, inputs, analog_ignore;
  bool bench = false;
};

// kerf run: false with "FILE:LINE: reason" and the configuration key to add
// for a program that uses a digital output (M62..M65, M7/M8, a user M-code)
// or an input (M66 P) with no line, or an analog number (M67/M68 E other
// than QtPlasmaC's E3 feed %, M66 E) not in [analog] ignore; a bench runs
// no program output at all. Each ignored analog number adds a note (once).
bool machine_can_run(job::GcodeProgram& prog, const MachineIo& io, std::string& error);

// "" when the machine can run action `a` (machine_can_run's rule for one
// action); otherwise why not, with the key to add.
std::string cannot_run(const JobAction& a, const MachineIo& io);

// The program's part of the run summary: dry run, constructs, notes.
void describe_program(const job::GcodeProgram& prog, RunSummary& sum);

}  // namespace kerf::control
