#include "control/job_stream.hpp"

#include <chrono>
#include <memory>
#include <utility>

#include "job/point_stream.hpp"

namespace kerf::control {

PointFileProducer::PointFileProducer() = default;

PointFileProducer::~PointFileProducer() {
  stopping_ = true;
  join();
}

void PointFileProducer::join() {
  if (thread_.joinable()) thread_.join();
}

bool PointFileProducer::start(const std::string& file, const JobStreamSetup& setup, JobRing& ring,
                              std::string& error) {
  auto in = std::make_unique<job::PointStream>();
  if (!in->open(file)) {
    error = file + ": " + in->reason();
    return false;
  }
  if (!fitter_.start(setup.criterion, job::Numeric::floating, setup.feed_mm_s, setup.window, error)) return false;
  fitter_.begin_path(in->file(), 0, setup.tol);
  stream_ = std::move(in);
  thread_ = std::thread([this, file, &ring] { run(file, ring); });
  return true;
}

// Waits while the ring is full (this is not the real-time thread).
bool PointFileProducer::put(JobRing& ring, const StreamItem& item) {
  while (!ring.try_push(item)) {
    if (stopping_) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return true;
}

void PointFileProducer::run(const std::string&, JobRing& ring) {
  job::PointStream& in = *stream_;
  const PathStreamFitter::Sink sink = [&](const StreamedSegment& s) {
    StreamItem item;
    item.seg = s;
    return put(ring, item);
  };
  StreamItem last;
  last.kind = StreamItem::Kind::end;
  std::string why;
  Status st = Status::ok;
  Vec2<double> p;
  for (;;) {
    const job::PointStream::Next got = in.next(p);
    if (got == job::PointStream::Next::end) break;
    if (got == job::PointStream::Next::error) {
      error_ = in.file() + ":" + std::to_string(in.line()) + ": " + in.reason();
      last.kind = StreamItem::Kind::error;
      break;
    }
    points_.fetch_add(1, std::memory_order_acq_rel);
    if (!fitter_.push(p, in.line(), sink, why, st)) {
      error_ = in.file() + ": " + why;
      last.kind = StreamItem::Kind::error;
      break;
    }
    if (stopping_) return;
  }
  if (last.kind == StreamItem::Kind::end && !fitter_.end_path(sink, why, st)) {
    error_ = in.file() + ": " + why;
    last.kind = StreamItem::Kind::error;
  }
  put(ring, last);
  ring.close();
}

}  // namespace kerf::control
