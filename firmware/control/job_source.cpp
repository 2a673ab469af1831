#include "control/job_source.hpp"

#include <algorithm>

#include "kerf/core/assert.hpp"

namespace kerf::control {

WholeJobSource::WholeJobSource(const Job& job) : job_(job), open_(job.paths.size()) {
  for (const CutPath& p : job.paths) {
    segments_ += p.segments.size();
    max_moves_ = std::max({max_moves_, p.before.size(), p.after.size()});
  }
}

SegmentPlace WholeJobSource::locate(std::size_t k) {
  SegmentPlace s;
  s.path = job_.path_of(k, s.index);
  const CutPath& p = job_.paths[s.path];
  s.start = s.index == 0 ? p.start : p.segments[s.index - 1].end;
  s.segment = p.segments[s.index];
  first_ = k - s.index;
  open_ = job_.paths.size();
  head_.first_segment = first_;
  return s;
}

const PathHead* WholeJobSource::open(std::size_t p) {
  if (p >= job_.paths.size()) return nullptr;
  if (p == open_ + 1) first_ += job_.paths[open_].segments.size();
  KERF_ASSERT((p == open_ || p == open_ + 1 || open_ == job_.paths.size()) && "paths are opened in order");
  open_ = p;
  const CutPath& c = job_.paths[p];
  head_.start = c.start;
  head_.torch = c.torch;
  head_.pierce_delay_s = c.pierce_delay_s;
  head_.first_segment = first_;
  head_.before = &c.before;
  head_.after = &c.after;
  return &head_;
}

Pull WholeJobSource::segment(std::size_t i, const hal::SegmentCommand*& out) {
  if (open_ >= job_.paths.size() || i >= job_.paths[open_].segments.size()) return Pull::end;
  out = &job_.paths[open_].segments[i];
  return Pull::ready;
}

const JobAction* WholeJobSource::action(std::size_t a) {
  return a < job_.actions.size() ? &job_.actions[a] : nullptr;
}

const JobAction* JobSource::replay_output(std::size_t path, std::size_t i) {
  if (i == 0) replay_action_ = replay_index_ = 0;
  for (const JobAction* a = action(replay_action_); a != nullptr && a->before_path < path; a = action(++replay_action_)) {
    if (a->kind != job::CanonKind::digital_out && a->kind != job::CanonKind::analog_out) continue;
    if (replay_index_++ == i) {
      ++replay_action_;
      return a;
    }
  }
  return nullptr;
}

ResumePoint resume_point(JobSource& source, const JournalState& state) {
  ResumePoint r;
  r.first = static_cast<std::size_t>(state.last_completed + 1);
  if (r.first >= source.segment_count()) {
    r.done = true;
    return r;
  }
  r.from = source.locate(r.first).start;
  if (r.first >= source.segment_count()) {  // a stream met its end before r.first
    r.done = true;
    return r;
  }
  if (state.has_cut_to && state.cut_to.segment == r.first) r.from = state.cut_to.at;
  return r;
}

}  // namespace kerf::control
