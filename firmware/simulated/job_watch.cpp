#include "simulated/job_watch.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace kerf::simulated {

void TimeBudget::add_segment(const Segment<double>& s, double feed_mm_s) {
  cut_mm += s.is_arc() ? s.radius() * 6.3 : distance(s.start, s.end);
  extent = std::max({extent, std::abs(s.end.x), std::abs(s.end.y)});
  if (feed_mm_s > 0) slowest_mm_min = slowest_mm_min > 0 ? std::min(slowest_mm_min, feed_mm_s * 60.0) : feed_mm_s * 60.0;
}

void TimeBudget::add_action(const control::JobAction& a) {
  waits_s += a.kind == job::CanonKind::pause ? operator_delay_s + 1.0 : a.value > 0 ? a.value : 0.0;
}

double TimeBudget::limit_s() const {
  const double feed = slowest_mm_min > 0 ? std::min(slowest_mm_min, cut_feed_mm_min) : cut_feed_mm_min;
  const double cut_s = feed > 0 ? cut_mm / (feed / 60.0) : 0.0;
  const double per_path = (rapid_mm_min > 0 ? 4.0 * extent / (rapid_mm_min / 60.0) : 0.0) + arc_ok_timeout_s +
                          pierce_delay_s + 2.0;
  return std::max(600.0, 3.0 * (cut_s + static_cast<double>(paths) * per_path + waits_s));
}

WatchedJobSource::WatchedJobSource(control::JobSource& inner, const TimeBudget& budget,
                                   std::function<void(const PulledSegment&)> on_segment)
    : inner_(inner), budget_(budget), on_segment_(std::move(on_segment)), ring_(kRecent) {}

control::SegmentPlace WatchedJobSource::locate(std::size_t k) {
  const control::SegmentPlace place = inner_.locate(k);
  located_ = true;
  located_at_ = k;
  located_start_ = place.start;
  return place;
}

const control::PathHead* WatchedJobSource::open(std::size_t p) {
  const control::PathHead* head = inner_.open(p);
  if (head == nullptr) {
    behind_ = behind_ || (inner_.path_count() == kUnknownCount && *inner_.error() == '\0');
    return head;
  }
  path_ = p;
  first_ = head->first_segment;
  head_start_ = head->start;
  if (p + 1 > paths_) {
    budget_.paths += p + 1 - paths_;
    paths_ = p + 1;
  }
  return head;
}

control::Pull WatchedJobSource::segment(std::size_t i, const hal::SegmentCommand*& out) {
  const control::Pull r = inner_.segment(i, out);
  if (r == control::Pull::later) behind_ = true;
  if (r != control::Pull::ready) return r;
  const std::size_t k = first_ + i;
  PulledSegment& slot = ring_[k % kRecent];
  if (slot.job == k) return r;  // pulled again (a restart): already noted
  // Where it starts: the previous segment's end, the pierce point, or where locate() put it.
  Vec2<double> from = head_start_;
  const PulledSegment* before = k > 0 ? recent(k - 1) : nullptr;
  if (i > 0 && before != nullptr && before->path == path_) from = before->segment.end;
  else if (i > 0 && located_ && located_at_ == k) from = located_start_;
  const hal::SegmentCommand& c = *out;
  slot.job = k;
  slot.path = path_;
  slot.segment = c.kind == SegmentKind::arc ? Segment<double>::arc(from, c.end, c.centre, c.dir)
                                            : Segment<double>::line(from, c.end);
  if (k + 1 > pulled_) {
    pulled_ = k + 1;
    budget_.add_segment(slot.segment, c.feed);
    if (on_segment_) on_segment_(slot);
  }
  return r;
}

const control::JobAction* WatchedJobSource::action(std::size_t a) {
  const control::JobAction* act = inner_.action(a);
  if (act != nullptr && a + 1 > actions_) {
    actions_ = a + 1;
    budget_.add_action(*act);
  }
  return act;
}

const PulledSegment* WatchedJobSource::recent(std::size_t k) const {
  const PulledSegment& slot = ring_[k % kRecent];
  return slot.job == k ? &slot : nullptr;
}

}  // namespace kerf::simulated
