// The producer thread of a streamed job (control/streamed_job.hpp): reads a
// G-code program (job::ProgramStream) or a point file's paths, fits each
// path as the whole job does (fit_program_path), applies the cutting rules,
// the soft limits, the machine's outputs and the dry-run holds path by path,
// and pushes the items over the ring (control/stream_job_source.hpp). It
// waits while the ring is full (it is not the real-time thread).
//
// Order on the ring, as the controller reads it: a path's head, its
// `before` moves (the carry of shorter-than-grid paths first), its segments;
// then, once the next path that reaches the job (or the file's end) is
// known, the path's `after` moves (at the end with the carry), its end, and
// the actions before the next path.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "control/point_paths.hpp"
#include "control/stream_job_source.hpp"
#include "control/streamed_job.hpp"
#include "io/point_file.hpp"
#include "job/program_stream.hpp"

namespace kerf::control {

class JobProducer {
 public:
  JobProducer() = default;
  ~JobProducer();  // stops after the item in hand and joins
  JobProducer(const JobProducer&) = delete;
  JobProducer& operator=(const JobProducer&) = delete;

  // Starts the thread over a program stream or a point file's paths (one
  // of the two). quiet: no cutting rule notes on stderr (a second reading,
  // for a resume's rewind).
  void start(std::unique_ptr<job::ProgramStream> program, std::unique_ptr<PointPaths> points,
             const StreamedJobSetup& setup, JobItemRing& ring, bool quiet);
  void stop();

  // Once the ring says error (or failed() is true): the error.
  bool failed() const { return failed_.load(std::memory_order_acquire); }
  bool ended() const { return ended_.load(std::memory_order_acquire); }
  const std::string& error() const { return error_; }  // "FILE:LINE: reason" (the fault's text)
  const std::string& say() const { return say_; }      // the line to print when refused before motion
  int exit_code() const { return exit_code_; }
  StreamTotals totals() const;

 private:
  void run();
  bool put(const JobItem& item);
  bool action(job::ProgramAction a);
  bool path(const io::PointFile& one, const std::vector<double>& feed, const job::ProgramPath& pp);
  bool flush(bool last);  // the previous path's after moves and end, and the actions after it
  bool finish();
  bool fail(std::string error, int rc, std::string say = {});
  const std::string& file() const;
  std::string file_;

  std::unique_ptr<job::ProgramStream> program_;
  std::unique_ptr<PointPaths> points_;
  StreamedJobSetup setup_;
  PathFitSettings fit_;
  JobItemRing* ring_ = nullptr;
  bool quiet_ = false;
  std::thread thread_;
  std::atomic<bool> stopping_{false}, failed_{false}, ended_{false};
  std::string error_, say_;
  int exit_code_ = 0;
  // The job so far.
  std::size_t program_paths_ = 0, kept_ = 0;
  std::vector<hal::SegmentCommand> carry_, after_;  // short paths' moves; the previous path's after
  bool have_previous_ = false;
  std::vector<job::ProgramAction> pending_;         // the actions after the previous path
  std::vector<std::pair<int, std::size_t>> ignored_analog_;  // noted once each
  mutable std::mutex mutex_;
  StreamTotals totals_;
};

}  // namespace kerf::control
