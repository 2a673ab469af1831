// A point file's cut paths fitted one by one into a controller Job: each
// path becomes a chain of arcs and lines at the cut feed, pierced at its
// first point. Shared by `kerf sim` and `kerf run`. Every segment is one the
// board runs, after the link's rounding (motion/segment_contract.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "config/cut_rules.hpp"
#include "control/cut_rule_note.hpp"
#include "control/job.hpp"
#include "control/journal.hpp"
#include "io/point_file.hpp"
#include "job/criterion.hpp"
#include "kerf/core/status.hpp"
#include "kerf/fit/fit.hpp"
#include "kerf/motion/segment_contract.hpp"

namespace kerf::control {

struct FittedJob {
  control::Job job;
  std::vector<fit::Piece<double>> pieces;  // in job order
  std::vector<std::size_t> piece_path;     // the path of each piece
  std::vector<std::size_t> path_point;     // each path's first point in the source file's points (its lines)
  std::size_t lines_for_arcs = 0;          // arcs too small for the link's grid, run as chords
  std::vector<CutRuleNote> cut_rules;      // where the cutting rules applied (for the report)
};

// The grid every segment link carries: integer micrometres in 32 bits
// (hal/modbus/REGISTERS.md; the CAN link takes any double, so 1 um is exact
// for it too). fit_paths emits every segment on it (motion/segment_contract.hpp).
inline constexpr motion::SegmentGrid kLinkGrid{1000, 2147483647};

// On failure returns false with `error` ("path N (line L): reason") and `status`.
// numeric: the fit's scalar type (job/criterion.hpp).
bool fit_paths(const io::PointFile& in, job::Criterion criterion, double tol, double feed_mm_s,
               FittedJob& out, std::string& error, Status& status,
               job::Numeric numeric = job::Numeric::floating);

// fit_paths for a command: on failure prints "kerf: FILE: reason" and
// returns the exit code (2 for bad input, 1 otherwise); 0 on success. With
// `rules`, applies the cutting rules (control/cut_rules.hpp) and prints
// "kerf: FILE: path N: ..." for each place one applied.
int fit_paths_or_say(const io::PointFile& in, job::Criterion criterion, double tol, double feed_mm_s,
                     FittedJob& out, job::Numeric numeric = job::Numeric::floating,
                     const config::CutRules* rules = nullptr);

// The job's journal for a run: none (empty path; the run starts at the
// job's beginning), a new one, or with `resume` the one a previous run left,
// and the point this run starts from. On failure prints
// "kerf: --journal: reason" and returns false.
bool open_journal(const std::string& path, bool resume, const control::Job& job,
                  std::unique_ptr<control::Journal>& out, control::ResumePoint& from);
// The same over a job source (a streamed job: control/streamed_job.hpp).
class JobSource;
bool open_journal(const std::string& path, bool resume, JobSource& job, std::unique_ptr<control::Journal>& out,
                  control::ResumePoint& from);

}  // namespace kerf::control
