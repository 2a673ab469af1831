// The producer side of the streaming job pipeline: a thread that reads a
// point file line by line (job/point_stream.hpp: one path), fits it in a
// bounded window (control/path_stream.hpp) and hands each segment over a
// bounded ring (control/stream_ring.hpp) as soon as it is decided. The
// consumer (the controller's side) only polls the ring: it never waits and
// never allocates. When the ring is full the producer waits (it is not the
// real-time thread). Memory: the window and the ring, whatever the file's length.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

#include "control/path_stream.hpp"
#include "control/stream_ring.hpp"

namespace kerf::job {
class PointStream;
}

namespace kerf::control {

struct StreamItem {
  enum class Kind : std::uint8_t { segment, end, error };
  Kind kind = Kind::segment;
  StreamedSegment seg;
};

using JobRing = StreamRing<StreamItem, 1024>;

struct JobStreamSetup {
  job::Criterion criterion = job::Criterion::band;
  double tol = 0.025;        // mm
  double feed_mm_s = 50.0;
  std::uint32_t window = 1024;
};

class PointFileProducer {
 public:
  PointFileProducer();
  // Stops the thread after its current line (a FIFO's read may wait for it).
  ~PointFileProducer();
  // Opens `file` and starts the thread. False with "FILE: reason" if the
  // file cannot be opened or the setup is refused (nothing started).
  bool start(const std::string& file, const JobStreamSetup& setup, JobRing& ring, std::string& error);
  // After an error item: "FILE:LINE: reason" or "FILE: path 1 (line L): reason".
  const std::string& error() const { return error_; }
  // Points read so far (any thread).
  std::uint64_t points_read() const { return points_.load(std::memory_order_acquire); }
  // After the end or error item: the fit's counts (forced commits among them).
  const PathStreamStats& stats() const { return fitter_.stats(); }
  void join();

 private:
  void run(const std::string& file, JobRing& ring);
  bool put(JobRing& ring, const StreamItem& item);

  PathStreamFitter fitter_;
  std::thread thread_;
  std::string error_;
  std::atomic<std::uint64_t> points_{0};
  std::atomic<bool> stopping_{false};
  std::unique_ptr<job::PointStream> stream_;  // opened in start()
};

}  // namespace kerf::control
