// A one-path point job as the producer thread streams it (control/job_stream.hpp),
// read by the controller as a JobSource (control/job_source.hpp): segment()
// pops the producer's ring and never waits (an empty ring that is still open
// is `later`). A stream that ends before the first pass's count (the file
// changed under the run) is an error, a fault, never a short "done". What must be known before anything moves, the journal's id
// and the segment count, comes from a first pass over the file (JobSummary).
// Memory: the ring, and the last kHistory segments, so that a restart after
// a reset can locate() the segment it resumes in (it lies within the board's
// queue of the last one sent, far fewer).
#pragma once

#include <array>
#include <string>

#include "control/job_source.hpp"
#include "control/job_stream.hpp"

namespace kerf::control {

struct JobSummary {
  JobId id{};
  std::size_t segments = 0;
};

class RingJobSource final : public JobSource {
 public:
  static constexpr std::size_t kHistory = 1024;
  // The ring is the producer's (not owned); `producer_error` is read once the ring says error.
  RingJobSource(JobRing& ring, const JobSummary& summary, const std::string& producer_error);
  JobId id() const override { return summary_.id; }
  std::size_t segment_count() const override { return summary_.segments; }
  std::size_t path_count() const override { return 1; }
  std::size_t max_moves() const override { return 0; }
  // Waits for the producer up to segment k, and for a full ring (or the
  // file's end) before anything moves (not in the steady cycle: start, resume).
  SegmentPlace locate(std::size_t k) override;
  const PathHead* open(std::size_t p) override;
  Pull segment(std::size_t i, const hal::SegmentCommand*& out) override;
  const JobAction* action(std::size_t) override { return nullptr; }
  const char* error() const override { return error_.c_str(); }
  // The segments popped from the ring so far.
  std::size_t popped() const { return popped_; }

 private:
  Pull pop();  // one more segment into the history
  Pull short_stream();
  const StreamedSegment& kept(std::size_t k) const { return history_[k % kHistory]; }

  JobRing& ring_;
  JobSummary summary_;
  const std::string& producer_error_;
  std::string error_;
  std::array<StreamedSegment, kHistory> history_{};
  std::size_t popped_ = 0;  // segments 0..popped_-1 came out of the ring
  bool ended_ = false, failed_ = false;
  PathHead head_;
  std::vector<hal::SegmentCommand> none_;  // no z moves
};

}  // namespace kerf::control
