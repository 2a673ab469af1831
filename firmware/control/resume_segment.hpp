// The rest of a job segment when a run resumes inside it (the journal's
// cut_to point, control/journal.hpp), made by the same contract as every
// other segment (motion/segment_contract.hpp): the resume point goes onto the
// link's grid and the rest through emit_on_grid, so the board never gets a
// segment that the fit could not have emitted. Without this a point a count
// past an arc's end gave an arc of sweep nearly 2 pi (a full circle cut).
#pragma once

#include "kerf/hal/segment_link.hpp"

namespace kerf::control {

struct ResumedSegment {
  bool whole = false;            // at (or within a count of, or past) its end: the segment was cut whole
  Vec2<double> from{};           // where the cut resumes, on the grid: the pierce point
  int count = 0;                 // 1 or 2 (an arc split as emit_on_grid splits it)
  hal::SegmentCommand segments[2]{};  // feed and torch the job segment's
  void clear() {
    whole = false;
    count = 0;
  }
};

// Job segment `seg`, which starts at `start`, resumed from `at`. A point that
// emit_on_grid cannot take (never seen: a resume point beyond the link's
// range) resumes at the segment's start: a little is cut again, no bad segment.
ResumedSegment resume_segment(const hal::SegmentCommand& seg, Vec2<double> start, Vec2<double> at);

}  // namespace kerf::control
