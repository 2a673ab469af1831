// A G-code program (job/gcode_program.hpp) fitted into a controller Job:
// each path at its own tolerance (G64 P, capped by fit.tol), each segment at
// the slowest feed programmed along it (F or the material's, times the feed
// %, capped by the machine's max feed), torch on or dry run, with the
// program's actions between the paths.
#pragma once

#include <string>

#include "control/fit_paths.hpp"
#include "control/run_report.hpp"
#include "job/gcode_program.hpp"

namespace kerf::control {

// On failure prints "kerf: FILE: reason" and returns the exit code (2 bad input, 1 otherwise); 0 on success.
// With `rules`, the cutting rules (control/cut_rules.hpp) then scale the feeds and add overcuts, as for a point file.
int fit_program_or_say(const job::GcodeProgram& prog, job::Criterion criterion, double tol, double feed_mm_s,
                       double max_feed_mm_s, FittedJob& out, job::Numeric numeric = job::Numeric::floating,
                       const config::CutRules* rules = nullptr);

// kerf run: false with "FILE:LINE: reason" for a program that needs what
// the machine does not have yet: program outputs and inputs (M7/M8 with a
// gas output, M62..M65 other than the torch, M66, M67/M68 other than the feed
// %, user M-codes that switch an output). hal::Gpio drives only the torch.
bool machine_can_run(const job::GcodeProgram& prog, std::string& error);

// The program's part of the run summary: dry run, constructs, notes.
void describe_program(const job::GcodeProgram& prog, RunSummary& sum);

}  // namespace kerf::control
