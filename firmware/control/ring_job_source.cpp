#include "control/ring_job_source.hpp"

#include <chrono>
#include <thread>

#include "kerf/core/assert.hpp"

namespace kerf::control {

RingJobSource::RingJobSource(JobRing& ring, const JobSummary& summary, const std::string& producer_error)
    : ring_(ring), summary_(summary), producer_error_(producer_error) {
  head_.before = head_.after = &none_;
}

Pull RingJobSource::pop() {
  if (failed_) return Pull::error;
  if (ended_) return Pull::end;
  StreamItem item;
  if (!ring_.try_pop(item)) return Pull::later;  // the end and error items come before the close
  if (item.kind == StreamItem::Kind::end) {
    if (popped_ != summary_.segments) return short_stream();
    ended_ = true;
    return Pull::end;
  }
  if (item.kind == StreamItem::Kind::error) {
    failed_ = true;
    error_ = producer_error_;  // written by the producer before it pushed the item
    return Pull::error;
  }
  if (popped_ == 0) head_.start = item.seg.from;
  history_[popped_ % kHistory] = item.seg;
  ++popped_;
  return Pull::ready;
}

// Not the job the first pass counted: the file changed under the run.
Pull RingJobSource::short_stream() {
  failed_ = true;
  error_ = "the stream ended after " + std::to_string(popped_) + " segments, the first pass counted " +
           std::to_string(summary_.segments) + " (the file changed since?)";
  return Pull::error;
}

SegmentPlace RingJobSource::locate(std::size_t k) {
  KERF_ASSERT(k < summary_.segments && k + kHistory >= popped_ && "a segment still in the history");
  // A full ring first (or the whole file): the cut then never waits for the
  // producer while the board's queue drains (a stop mid-cut marks the part).
  while (ring_.size() < JobRing::kCapacity && !ring_.closed())
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  while (popped_ <= k) {
    const Pull p = pop();
    if (p == Pull::later) std::this_thread::sleep_for(std::chrono::microseconds(200));
    else if (p != Pull::ready) break;
  }
  SegmentPlace s;
  if (popped_ <= k) {  // the stream ended early or failed: segment() says so, a fault before anything moves
    if (!failed_) short_stream();
    return s;
  }
  s.index = k;
  s.segment = kept(k).cmd;
  s.start = kept(k).from;
  return s;
}

const PathHead* RingJobSource::open(std::size_t p) {
  return p == 0 ? &head_ : nullptr;
}

Pull RingJobSource::segment(std::size_t i, const hal::SegmentCommand*& out) {
  if (i >= popped_) {
    const Pull p = pop();
    if (p != Pull::ready) return p;
  }
  KERF_ASSERT(i < popped_ && i + kHistory >= popped_ && "segments asked in order");
  out = &kept(i).cmd;
  return Pull::ready;
}

}  // namespace kerf::control
