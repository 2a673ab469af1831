// What the controller reads of a job (issue 24): its paths in order, each
// path's segments one at a time, and the program's actions; never the job as
// a whole. A source that streams (a file read, fitted and handed on by a
// producer thread) keeps only a bounded look-ahead; WholeJobSource is the
// source over a Job held in memory (the tests, kerf check, and the oracle a
// streamed run is compared against).
//
// The cycle calls open(), segment() and action(): none of them may allocate,
// block or wait on the disk. locate() runs outside the steady cycle (start of
// a run, a resume, a restart after a reset) and may re-read the job up to
// the segment asked for.
#pragma once

#include <cstddef>
#include <vector>

#include "control/job.hpp"

namespace kerf::control {

// A path as the controller needs it before its first segment.
struct PathHead {
  Vec2<double> start{};           // the pierce point
  bool torch = true;              // false: a dry-run path
  double pierce_delay_s = -1;     // < 0: the controller's
  std::size_t first_segment = 0;  // the job segment number of its segment 0
  // z axis (CutPath::before/after), never null. `after` is complete once
  // segment() has reported the path's end.
  const std::vector<hal::SegmentCommand>* before = nullptr;
  const std::vector<hal::SegmentCommand>* after = nullptr;
};

// Where job segment k lies (locate()).
struct SegmentPlace {
  std::size_t path = 0;   // the path holding it
  std::size_t index = 0;  // its index in that path
  Vec2<double> start{};   // the pierce point or the previous segment's end
  hal::SegmentCommand segment{};
};

// segment()'s answer: here it is, not yet (a stream's producer is behind:
// ask again next cycle), the open path has no segment i, or the source
// failed (error() says why: a bad line met while streaming; a fault).
enum class Pull : std::uint8_t { ready, later, end, error };

class JobSource {
 public:
  virtual ~JobSource() = default;
  // The journal's identity of the job, and its size: a stream knows its
  // size only once its producer has ended (kUnknownCount, the largest
  // size_t, until then; the job is done when the source ends).
  static constexpr std::size_t kUnknownCount = static_cast<std::size_t>(-1);
  virtual JobId id() const = 0;
  virtual std::size_t segment_count() const = 0;
  virtual std::size_t path_count() const = 0;
  // The most moves one path's before or after list holds (the controller
  // reserves its travel queue once, at start).
  virtual std::size_t max_moves() const = 0;
  // Job segment k (< segment_count()); its path becomes the one open() gives next.
  // A stream whose job ends before k: segment_count() is then known (<= k).
  virtual SegmentPlace locate(std::size_t k) = 0;
  // Path p's head, p the path locate() gave or the one after the last opened;
  // null: not available yet (the controller waits at rest and asks again),
  // or no such path (path_count() then says p is past the last), or error().
  // Never null for the path locate() gave (locate() waits for it).
  // The head and its lists stay valid until the next open() or locate().
  virtual const PathHead* open(std::size_t p) = 0;
  // Segment i of the open path, asked in order; the ones before i are not
  // asked again. *out stays valid until the next call.
  virtual Pull segment(std::size_t i, const hal::SegmentCommand*& out) = 0;
  // The program's a-th action (in order; each runs before path before_path,
  // or after the last); null past the last. Available: every action before
  // the open path, and the outputs (M62..M68) before it, for a restart's replay.
  virtual const JobAction* action(std::size_t a) = 0;
  // The i-th output (M62..M68) a restart sets again before path `path`, i
  // counting from 0 in order; null past the last. The default: each output
  // action before the path, in program order (a stream keeps each output's
  // latest value instead: control/stream_job_source.hpp).
  virtual const JobAction* replay_output(std::size_t path, std::size_t i);
  // The oldest action number action() still gives (a stream keeps the last few).
  virtual std::size_t first_action() const { return 0; }
  // After Pull::error: "FILE:LINE: reason".
  virtual const char* error() const { return ""; }

 private:
  std::size_t replay_action_ = 0, replay_index_ = 0;  // the default replay_output's place
};

// The source over a whole Job in memory (not owned; it must outlive the source).
class WholeJobSource final : public JobSource {
 public:
  explicit WholeJobSource(const Job& job);
  JobId id() const override { return job_.id(); }
  std::size_t segment_count() const override { return segments_; }
  std::size_t path_count() const override { return job_.paths.size(); }
  std::size_t max_moves() const override { return max_moves_; }
  SegmentPlace locate(std::size_t k) override;
  const PathHead* open(std::size_t p) override;
  Pull segment(std::size_t i, const hal::SegmentCommand*& out) override;
  const JobAction* action(std::size_t a) override;

 private:
  const Job& job_;
  std::size_t segments_ = 0, max_moves_ = 0;
  std::size_t first_ = 0;  // first_segment of path 0 .. : kept for the open path only
  std::size_t open_ = 0;   // the open path (== path_count(): none)
  PathHead head_;
};

// From a journal's state: the first segment not known complete, and the
// point up to which it was already cut.
ResumePoint resume_point(JobSource& source, const JournalState& state);

}  // namespace kerf::control
