// A cutting job as the controller runs it: cut paths in order, each a chain
// of fitted segments that starts where the torch pierces. Segments are
// numbered 0..N-1 across the whole job; the journal and the report speak of
// those numbers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "control/journal.hpp"
#include "job/gcode_program.hpp"
#include "kerf/hal/segment_link.hpp"

namespace kerf::control {

struct CutPath {
  Vec2<double> start{};                      // the pierce point
  std::vector<hal::SegmentCommand> segments; // end, centre, dir, feed; seq is set when sent
  bool torch = true;                         // false: a dry-run path, run with the torch off
  double pierce_delay_s = -1;                // < 0: the controller's (the material's otherwise)
  // With a z axis (job/gcode_program.hpp ProgramMove): the moves, torch off,
  // that lead to the pierce point and that run right after the path; z moves
  // (z_move) and XY rapids. Not job segments: like the travel, they are sent
  // again by a resumed run (a z move goes to an absolute z). A z move's XY
  // end is set when it is sent (where the axes then stand).
  std::vector<hal::SegmentCommand> before, after;
};

// What a G-code program does between its paths, at rest: dwell, pause,
// outputs, waits, tool change, feed %, end (job/gcode_program.hpp).
using JobAction = job::ProgramAction;

struct Job {
  std::vector<CutPath> paths;
  std::vector<JobAction> actions;  // in order; each runs before paths[before_path] (or at the end)
  // Where the fit's bounded window forced a commit (control/path_stream.hpp):
  // those paths may have more pieces than the fewest. For the run report.
  std::size_t forced_commits = 0;

  std::size_t segment_count() const;
  // The path holding job segment k, and k's index inside it.
  std::size_t path_of(std::size_t k, std::size_t& index_in_path) const;
  // Where job segment k starts (the pierce point or the previous segment's end).
  Vec2<double> segment_start(std::size_t k) const;
  const hal::SegmentCommand& segment(std::size_t k) const;
  // Identifies the job for the journal: FNV-1a over every path and segment.
  JobId id() const;
};

// Where a (resumed) run starts: job segment `first`, cut from `from` (its
// start, or the point a previous run's torch went off at).
struct ResumePoint {
  std::size_t first = 0;
  Vec2<double> from{};
  bool done = false;  // nothing left to cut
};

// A dry run: every path with the torch off (no pierce, no arc-OK wait);
// outputs_too: the program's outputs that would switch on (gas) are dropped.
void hold_outputs_off(Job& job, bool outputs_too);

// From a journal's state: the first segment not known complete, and the
// point up to which it was already cut.
ResumePoint resume_point(const Job& job, const JournalState& state);

}  // namespace kerf::control
