// The progress journal: what of a job has been cut, kept on disk so that
// `--resume` after a fault, a crash or a kill -9 finishes the job with every
// segment cut exactly once.
//
// Two kinds of record:
// - completed(k): job segment k (0-based, in job order) ran to its end.
//   Appended and fdatasync'd before the call returns, so it survives a power
//   loss. The controller records it in the cycle the board reports the
//   segment done, before any record that follows.
// - cut_to(k, point): segment k has been cut (torch on) from its start up to
//   `point`. Overwritten in place without a sync: it survives a
//   crash or kill -9 (the page cache outlives the process), not a power loss.
// Every record carries a checksum; a torn or corrupt tail is ignored on
// reading (and reported), never trusted. A torn `done k` therefore means k is
// not known done: it is cut again on resume (from the cut_to slot's point).
// The format is text lines (control/journal_record.hpp), readable with `cat`.
//
// The controller does not call these in its cycle: it queues them to a
// JournalWriter (control/journal_writer.hpp), whose thread writes and syncs
// them in order; completed(k, false) and sync() let it sync a batch at once.
//
// completed(k) takes segments in order: k <= last_completed + 1 (a repeat is
// journalled and counted as a duplicate; a gap is refused). cut_to() does not
// allocate. One process at a time: the file is flock()ed while open.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "kerf/geom/vec2.hpp"

namespace kerf::control {

// Which job a journal belongs to: resuming a different job is refused.
struct JobId {
  std::uint64_t hash = 0;      // FNV-1a over the job's segments (the controller computes it)
  std::uint32_t segments = 0;  // segments in the job
};

struct CutPoint {
  std::uint32_t segment = 0;  // job segment index
  Vec2<double> at{};          // mm, on that segment
};

struct JournalState {
  JobId job;
  std::int64_t last_completed = -1;  // highest completed segment, -1 for none
  bool has_cut_to = false;           // a cut_to record for segment last_completed + 1
  CutPoint cut_to;
  std::uint64_t executed_total = 0;  // completed records over every run (resumes included)
  std::uint64_t duplicates = 0;      // completed records for a segment already completed
  std::uint32_t runs = 0;            // create() and each resume() count one
  bool finished = false;             // the job reached its end
  bool torn_tail = false;            // reading stopped at a corrupt record
  bool cut_slot_corrupt = false;     // the cut_to slot failed its checksum (has_cut_to false)
};

class Journal {
 public:
  // A new journal for `job` at `path`; an existing file is replaced
  // atomically (written to a temp file, synced, renamed).
  static std::unique_ptr<Journal> create(const std::string& path, const JobId& job,
                                         std::string& error);
  // Reopens `path` to resume `job`. Refuses a missing file, another job
  // (hash or segment count differs) or a finished one, with the reason.
  static std::unique_ptr<Journal> resume(const std::string& path, const JobId& job,
                                         std::string& error);
  // Reads a journal without opening it for writing (reports, tests).
  static bool read(const std::string& path, JournalState& state, std::string& error);

  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  bool completed(std::uint32_t segment, bool sync = true);  // appended (and synced)
  bool sync();                            // every appended record on disk (fdatasync)
  bool cut_to(const CutPoint& p);         // in place, not synced
  bool finished();                        // appended and synced
  const JournalState& state() const { return state_; }
  const char* last_error() const { return error_.c_str(); }

 private:
  Journal() = default;
  bool append(const char* text, std::size_t n, bool sync = true);
  void fail(const char* what, int err);
  int fd_ = -1;
  std::uint64_t append_at_ = 0;  // file offset of the next appended record
  std::string path_;
  JournalState state_;
  std::string error_;
};

}  // namespace kerf::control
