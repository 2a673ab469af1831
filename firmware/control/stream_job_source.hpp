// The consumer side of a streamed job (control/streamed_job.hpp): a
// JobSource over the producer's ring of path heads, z moves, segments and
// actions, many paths a job. The cycle's calls (open, segment, action) only
// pop the ring: they never wait and never allocate (the move lists are
// reserved once, the histories are fixed arrays); an empty ring is `later`.
//
// The job's size is known once the producer's end item has been popped:
// segment_count() and path_count() are kUnknownCount until then, and open()
// of the path after the last gives null with path_count() then known.
//
// Memory, whatever the job's length: the last kHistory segments (with their
// fitted pieces: the trace recorder's, and a restart's locate()), the last
// kActions actions, and the latest value of each program output (at most
// kOutputs of them) for a restart's replay: the outputs are set again to the
// values the actions before the path left, each once, in the order of their
// last setting (the same state as the whole job's replay of every action).
// locate(k) of a segment behind the history, or in a path before the open
// one, asks `rewind` for a new ring read from the file's start.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "control/job_source.hpp"
#include "control/path_stream.hpp"
#include "control/stream_ring.hpp"

namespace kerf::control {

// One item of the producer's ring, in job order: per path its head, its
// `before` moves, its segments, its `after` moves and its end; the actions
// between paths; the job's end or an error.
struct JobItem {
  enum class Kind : std::uint8_t { head, before, segment, after, path_end, action, end, error };
  Kind kind = Kind::segment;
  std::uint32_t moves = 0;     // head: its before moves
  bool torch = true;           // head
  double pierce_delay_s = -1;  // head
  StreamedSegment seg;         // head: seg.from is the pierce point; before, after: seg.cmd; segment
  JobAction action;            // action (before_path: the job's path number)
};

using JobItemRing = StreamRing<JobItem, 1024>;

class StreamJobSource final : public JobSource {
 public:
  static constexpr std::size_t kHistory = 1024;
  static constexpr std::size_t kActions = 1024;
  static constexpr std::size_t kOutputs = 64;
  static constexpr std::size_t kMaxMoves = 1024;  // z moves before or after one path (the producer refuses more)
  // A new ring read from the file's start (locate() behind the history);
  // null when it cannot be had (the error says why).
  using Rewind = std::function<JobItemRing*()>;

  // The producer's "FILE:LINE: reason", asked once the ring says error.
  using ErrorText = std::function<std::string()>;
  StreamJobSource(JobId id, JobItemRing* ring, Rewind rewind, ErrorText error_text);

  JobId id() const override { return id_; }
  std::size_t segment_count() const override { return ended_ ? popped_ : kUnknownCount; }
  std::size_t path_count() const override { return ended_ ? paths_ : kUnknownCount; }
  std::size_t max_moves() const override { return kMaxMoves; }
  SegmentPlace locate(std::size_t k) override;
  const PathHead* open(std::size_t p) override;
  Pull segment(std::size_t i, const hal::SegmentCommand*& out) override;
  const JobAction* action(std::size_t a) override;
  const JobAction* replay_output(std::size_t path, std::size_t i) override;
  std::size_t first_action() const override;
  const char* error() const override { return error_.c_str(); }

  // Segment k's fitted piece and path while it is in the history; null otherwise.
  const fit::Piece<double>* piece(std::size_t k, std::size_t* path) const;
  std::size_t popped() const { return popped_; }
  bool ended() const { return ended_; }

 private:
  struct Kept {
    StreamedSegment seg;
    std::size_t path = 0;
  };
  struct Output {
    JobAction last;     // its latest setting
    std::size_t at = 0; // the action number of that setting (replay order)
  };
  void reset(JobItemRing* ring);
  bool pop();  // one item; false when the ring is empty (or the stream is over)
  void take(const JobItem& item);
  void note_output(const JobAction& a, std::size_t number);
  void fail(std::string why);

  JobId id_;
  JobItemRing* ring_;
  Rewind rewind_;
  ErrorText producer_error_;
  std::string error_;
  bool ended_ = false, failed_ = false;
  // Segments: 0..popped_-1 came out of the ring; the last kHistory are kept.
  std::array<Kept, kHistory> history_{};
  std::size_t popped_ = 0;
  // Paths: paths_ heads popped; the newest is path paths_ - 1 (the open one).
  std::size_t paths_ = 0;
  std::size_t opened_ = kUnknownCount;  // the path open() last gave
  bool have_head_ = false, path_done_ = false;
  std::uint32_t before_left_ = 0;
  PathHead head_;
  std::vector<hal::SegmentCommand> before_, after_;  // reserved kMaxMoves
  // Actions: 0..actions_-1 popped, the last kActions kept.
  std::array<JobAction, kActions> actions_kept_{};
  std::size_t actions_ = 0;
  // Outputs for a restart's replay: each output's latest value from the
  // actions before the newest head (`outputs_`), and before the actions of
  // the newest group (`outputs_prev_`, for a replay before that path).
  std::array<Output, kOutputs> outputs_{}, outputs_prev_{};
  std::size_t n_outputs_ = 0, n_outputs_prev_ = 0;
  std::size_t group_ = 0;  // before_path of the newest action group
  std::array<std::size_t, kOutputs> replay_order_{};
  std::size_t replay_n_ = 0, replay_path_ = kUnknownCount;
};

}  // namespace kerf::control
