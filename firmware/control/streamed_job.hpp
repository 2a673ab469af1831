// A job streamed from its file to the controller (issue 24): `kerf run` and
// `kerf sim` cut the first path before the file has been read to its end.
//
// open() hashes the file's bytes with the fit's settings (the journal's id:
// no fit, one fast read) and starts a producer thread. The producer reads the
// file, a G-code program through job::open_program_stream or a point file of
// one or many paths, fits each path exactly as the whole-job code does
// (control/program_job.hpp fit_program_path: the same segments bit for bit,
// feeds per piece, cutting rules, z moves before and after, the carry of
// paths shorter than the link's grid, the actions' before_path), holds the
// torch and the outputs off for a bench or a dry run (hold_outputs_off),
// checks each action against the machine (machine_can_run) and each path
// against the soft limits, and hands path heads, segments and actions over a
// bounded ring to source(), the JobSource the controller reads.
//
// The segment count is not known before the producer ends:
// source().segment_count() is kUnknownCount until then, and the job is done
// when the source ends. prime() waits, before anything moves, until the ring
// is full or the producer has reached the file's end: a short bad job is
// refused before motion (FILE:LINE, exit 2) as the whole job was; an error
// met later ends the stream with `job: FILE:LINE: reason`, a fault (torch
// off, motion stopped on the path, progress kept in the journal).
//
// Resume: source().locate(k) reads and fits the file again from its start
// up to segment k when k is not in its history (the fit is deterministic);
// another file or other settings have another id, which the journal refuses.
//
// Threads: open(), prime(), source() and piece() belong to the controller's
// thread; totals() may be called from any thread, except while source().locate()
// reads the file again (a restart after a reset behind the history: it
// replaces the producer).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/cut_rules.hpp"
#include "control/cut_rule_note.hpp"
#include "control/job_source.hpp"
#include "control/program_job.hpp"
#include "job/criterion.hpp"
#include "job/gcode_program.hpp"
#include "job/machine_state.hpp"
#include "kerf/fit/fit.hpp"
#include "kerf/motion/soft_limits.hpp"

namespace kerf::control {

// What the producer fits and checks with (kerf run's configuration).
struct StreamedJobSetup {
  job::Criterion criterion = job::Criterion::band;
  job::Numeric numeric = job::Numeric::floating;
  double tol = 0.025;              // mm (a program's G64 P may lower it per path)
  double feed_mm_s = 50.0;         // the cut feed
  double max_feed_mm_s = 1e9;      // the machine's (caps a program's feeds)
  std::optional<config::CutRules> rules;             // [cut]: holes, small arcs, overcut
  std::optional<motion::SoftLimits<double>> limits;  // each path before its head is handed on
  std::optional<MachineIo> io;     // kerf run: each action checked as machine_can_run does
  bool torch_off = false;          // a bench or --dry-run: every path with the torch off
  bool outputs_off = false;        // --dry-run: outputs that would switch on are dropped
  // G-code programs.
  job::InterpSettings interp;
  job::MachineState state;
};

// What the run report needs, as it accumulates (complete once `ended`).
struct StreamTotals {
  bool gcode = false;
  bool ended = false;              // the producer reached the file's end
  bool failed = false;             // the producer stopped on an error
  std::size_t paths = 0;           // paths handed on (shorter than the grid: not counted)
  std::size_t segments = 0;        // segments handed on
  std::size_t lines_for_arcs = 0;  // arcs too small for the link's grid, run as chords
  std::size_t forced_commits = 0;  // where the fit's window forced a commit
  std::vector<CutRuleNote> cut_rules;
  // G-code: the program's facts (job::ProgramStream::summary: constructs,
  // notes, final state, dry_run, z_moves, final_z); complete once `ended`.
  job::GcodeProgram summary;
};

class StreamedJob {
 public:
  // The segments (with their fitted pieces) the source keeps behind the
  // newest one popped: a restart after a reset and the trace recorder read them.
  static constexpr std::size_t kHistory = 1024;
  // source().segment_count() before the producer has ended.
  static constexpr std::size_t kUnknownCount = static_cast<std::size_t>(-1);

  StreamedJob();
  ~StreamedJob();  // stops and joins the producer
  StreamedJob(const StreamedJob&) = delete;
  StreamedJob& operator=(const StreamedJob&) = delete;

  // Hashes `file` (its bytes and the setup's fit settings: the id) and
  // starts the producer. 0, or the exit code (2 bad input, 1 otherwise) with
  // "FILE:LINE: reason" or "FILE: reason" in `error`; nothing started then.
  int open(const std::string& file, const StreamedJobSetup& setup, std::string& error);
  // Before anything moves: waits until the ring is full or the producer has
  // reached the file's end. 0, or the exit code with the producer's error
  // (the job is refused before motion, as a whole job would be).
  int prime(std::string& error);

  // What the controller reads (valid from open() to the destructor).
  JobSource& source();
  // The journal's id: FNV-1a over the file's bytes and the fit settings;
  // its segment count is JobId's "unknown" (0xffffffff): a stream is identified by its bytes.
  JobId id() const;
  const std::string& file() const;

  // The fitted piece of job segment k (point indices from its path's first
  // point) and the number of the path holding it, while k is among the last
  // kHistory segments popped; null otherwise. The controller's thread.
  const fit::Piece<double>* piece(std::size_t k, std::size_t* path = nullptr) const;

  // A copy of the totals so far (any thread).
  StreamTotals totals() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace kerf::control
