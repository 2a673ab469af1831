#include "control/job.hpp"

#include <vector>

#include "control/fnv1a.hpp"
#include "kerf/core/assert.hpp"

namespace kerf::control {

std::size_t Job::segment_count() const {
  std::size_t n = 0;
  for (const CutPath& p : paths) n += p.segments.size();
  return n;
}

std::size_t Job::path_of(std::size_t k, std::size_t& index_in_path) const {
  for (std::size_t p = 0; p < paths.size(); ++p) {
    if (k < paths[p].segments.size()) {
      index_in_path = k;
      return p;
    }
    k -= paths[p].segments.size();
  }
  KERF_ASSERT(false && "segment index past the job's end");
  return paths.size();
}

const hal::SegmentCommand& Job::segment(std::size_t k) const {
  std::size_t i = 0;
  const std::size_t p = path_of(k, i);
  return paths[p].segments[i];
}

Vec2<double> Job::segment_start(std::size_t k) const {
  std::size_t i = 0;
  const std::size_t p = path_of(k, i);
  return i == 0 ? paths[p].start : paths[p].segments[i - 1].end;
}

JobId Job::id() const {
  Fnv1a f;
  f.value(static_cast<std::uint64_t>(paths.size()));
  for (const CutPath& p : paths) {
    f.value(p.start.x);
    f.value(p.start.y);
    f.value(static_cast<std::uint64_t>(p.segments.size()));
    if (!p.torch) f.value(std::uint64_t{0xd27});  // a dry run is another job (point jobs keep their ids)
    for (const hal::SegmentCommand& s : p.segments) {
      f.value(static_cast<std::uint64_t>(s.kind == SegmentKind::arc ? 1 + (s.dir > 0) : 0));
      f.value(s.end.x);
      f.value(s.end.y);
      if (s.kind == SegmentKind::arc) {
        f.value(s.centre.x);
        f.value(s.centre.y);
      }
    }
    // z axis: the moves between paths (none without one: those jobs keep their ids).
    for (const auto* moves : {&p.before, &p.after})
      for (const hal::SegmentCommand& m : *moves) {
        f.value(static_cast<std::uint64_t>(m.z_move ? 0x2d : 0x27));
        f.value(m.z_move ? m.z : m.end.x);
        f.value(m.end.y);
      }
  }
  for (const JobAction& a : actions) {
    f.value(static_cast<std::uint64_t>(a.kind) << 32 | a.before_path);
    f.value(a.value);
  }
  return {f.h, static_cast<std::uint32_t>(segment_count())};
}

ResumePoint resume_point(const Job& job, const JournalState& state) {
  ResumePoint r;
  const std::size_t n = job.segment_count();
  r.first = static_cast<std::size_t>(state.last_completed + 1);
  if (r.first >= n) {
    r.done = true;
    return r;
  }
  r.from = job.segment_start(r.first);
  if (state.has_cut_to && state.cut_to.segment == r.first) r.from = state.cut_to.at;
  return r;
}

void hold_outputs_off(Job& job, bool outputs_too) {
  for (CutPath& p : job.paths) {
    p.torch = false;
    for (hal::SegmentCommand& c : p.segments) c.torch = false;
  }
  if (!outputs_too) return;
  std::erase_if(job.actions, [](const JobAction& a) {
    return (a.kind == job::CanonKind::digital_out || a.kind == job::CanonKind::analog_out) && a.value != 0;
  });
}

}  // namespace kerf::control
