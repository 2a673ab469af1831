#include "control/stream_job_source.hpp"

#include <chrono>
#include <thread>
#include <utility>

namespace kerf::control {

namespace {

bool is_output(const JobAction& a) {
  return a.kind == job::CanonKind::digital_out || a.kind == job::CanonKind::analog_out;
}

void nap() { std::this_thread::sleep_for(std::chrono::microseconds(200)); }

}  // namespace

StreamJobSource::StreamJobSource(JobId id, JobItemRing* ring, Rewind rewind, ErrorText error_text)
    : id_(id), ring_(ring), rewind_(std::move(rewind)), producer_error_(std::move(error_text)) {
  before_.reserve(kMaxMoves);
  after_.reserve(kMaxMoves);
  head_.before = &before_;
  head_.after = &after_;
}

void StreamJobSource::reset(JobItemRing* ring) {
  ring_ = ring;
  ended_ = failed_ = false;
  error_.clear();
  popped_ = paths_ = actions_ = 0;
  opened_ = kUnknownCount;
  have_head_ = path_done_ = false;
  before_left_ = 0;
  before_.clear();
  after_.clear();
  n_outputs_ = n_outputs_prev_ = 0;
  group_ = 0;
  replay_path_ = kUnknownCount;
}

void StreamJobSource::fail(std::string why) {
  if (failed_) return;
  failed_ = true;
  error_ = std::move(why);
}

bool StreamJobSource::pop() {
  if (ended_ || failed_ || ring_ == nullptr) return false;
  JobItem item;
  if (!ring_->try_pop(item)) return false;
  take(item);
  return true;
}

void StreamJobSource::take(const JobItem& item) {
  switch (item.kind) {
    case JobItem::Kind::head:
      ++paths_;
      have_head_ = true;
      path_done_ = false;
      head_.start = item.seg.from;
      head_.torch = item.torch;
      head_.pierce_delay_s = item.pierce_delay_s;
      head_.first_segment = popped_;
      before_.clear();
      after_.clear();
      before_left_ = item.moves;
      break;
    case JobItem::Kind::before:
      if (before_.size() < kMaxMoves) before_.push_back(item.seg.cmd);
      if (before_left_ > 0) --before_left_;
      break;
    case JobItem::Kind::segment:
      history_[popped_ % kHistory] = {item.seg, paths_ - 1};
      ++popped_;
      break;
    case JobItem::Kind::after:
      if (after_.size() < kMaxMoves) after_.push_back(item.seg.cmd);
      break;
    case JobItem::Kind::path_end: path_done_ = true; break;
    case JobItem::Kind::action:
      if (actions_ == 0 || item.action.before_path > group_) {  // a new group: the state before it
        outputs_prev_ = outputs_;
        n_outputs_prev_ = n_outputs_;
        group_ = item.action.before_path;
      }
      actions_kept_[actions_ % kActions] = item.action;
      if (is_output(item.action)) note_output(item.action, actions_);
      ++actions_;
      break;
    case JobItem::Kind::end: ended_ = true; break;
    case JobItem::Kind::error: fail(producer_error_()); break;
  }
}

void StreamJobSource::note_output(const JobAction& a, std::size_t number) {
  for (std::size_t i = 0; i < n_outputs_; ++i)
    if (outputs_[i].last.kind == a.kind && outputs_[i].last.index == a.index) {
      outputs_[i] = {a, number};
      return;
    }
  if (n_outputs_ == kOutputs) {
    fail("more than 64 program outputs: a streamed job keeps at most 64 for a restart");
    return;
  }
  outputs_[n_outputs_++] = {a, number};
}

SegmentPlace StreamJobSource::locate(std::size_t k) {
  SegmentPlace s;
  // A full ring first (or the whole file): the cut then never waits for the
  // producer while the board's queue drains.
  const auto fill = [this] {
    while (ring_ != nullptr && ring_->size() < JobItemRing::kCapacity && !ring_->closed()) nap();
  };
  fill();
  const bool kept = k < popped_ && k + kHistory >= popped_ && paths_ > 0 && k >= head_.first_segment;
  if (!kept && k < popped_) {  // behind the history, or in a path before the open one: read again
    JobItemRing* ring = rewind_ ? rewind_() : nullptr;
    if (ring == nullptr) {
      fail("the job cannot be read again from its start");
    } else {
      reset(ring);
      fill();
    }
  }
  while (popped_ <= k && !ended_ && !failed_)
    if (!pop()) nap();
  // The head's moves come before its first segment: complete once k is popped.
  opened_ = paths_ > 0 ? paths_ - 1 : 0;
  if (popped_ <= k) return s;  // the job ended (segment_count() says so) or failed (error())
  s.path = history_[k % kHistory].path;
  s.index = k - head_.first_segment;
  s.segment = history_[k % kHistory].seg.cmd;
  s.start = history_[k % kHistory].seg.from;
  return s;
}

const PathHead* StreamJobSource::open(std::size_t p) {
  if (failed_) return p == opened_ ? &head_ : nullptr;  // after a failed locate(): a fault before anything moves
  if (paths_ > 0 && p == paths_ - 1) {
    if (before_left_ > 0) {  // its moves still coming
      while (before_left_ > 0 && pop()) {}
      if (before_left_ > 0) return nullptr;
    }
    opened_ = p;
    return &head_;
  }
  if (p != paths_) return nullptr;
  // The next path: the rest of the open one, the actions before p, its head and moves.
  while (paths_ <= p || before_left_ > 0)
    if (!pop()) return nullptr;
  opened_ = p;
  return &head_;
}

Pull StreamJobSource::segment(std::size_t i, const hal::SegmentCommand*& out) {
  const std::size_t g = head_.first_segment + i;
  while (popped_ <= g) {
    if (failed_) return Pull::error;
    if (path_done_ || ended_) return Pull::end;
    if (!pop()) return failed_ ? Pull::error : Pull::later;
  }
  out = &history_[g % kHistory].seg.cmd;
  return Pull::ready;
}

const JobAction* StreamJobSource::action(std::size_t a) {
  return a < actions_ && a + kActions >= actions_ ? &actions_kept_[a % kActions] : nullptr;
}

const JobAction* StreamJobSource::replay_output(std::size_t path, std::size_t i) {
  // Before the newest action group's path: the state before that group.
  const bool before_group = actions_ > 0 && path <= group_;
  const std::array<Output, kOutputs>& table = before_group ? outputs_prev_ : outputs_;
  const std::size_t n = before_group ? n_outputs_prev_ : n_outputs_;
  if (i == 0 || replay_path_ != path) {  // each output once, in the order of its last setting
    replay_path_ = path;
    replay_n_ = n;
    for (std::size_t j = 0; j < n; ++j) {
      std::size_t at = j;
      while (at > 0 && table[replay_order_[at - 1]].at > table[j].at) {
        replay_order_[at] = replay_order_[at - 1];
        --at;
      }
      replay_order_[at] = j;
    }
  }
  return i < replay_n_ ? &table[replay_order_[i]].last : nullptr;
}

std::size_t StreamJobSource::first_action() const { return actions_ > kActions ? actions_ - kActions : 0; }

const fit::Piece<double>* StreamJobSource::piece(std::size_t k, std::size_t* path) const {
  if (k >= popped_ || k + kHistory < popped_) return nullptr;
  if (path != nullptr) *path = history_[k % kHistory].path;
  return &history_[k % kHistory].seg.piece;
}

}  // namespace kerf::control
