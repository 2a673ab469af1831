// What `kerf sim` learns of a job as the controller reads it: a JobSource
// that passes every call through to the real one (a job held whole or one
// that streams) and notes what goes by, in memory that does not grow with
// the job. The trace's deviation, the progress line, the run's time limit
// and the plot read it instead of the whole fitted job:
//   - the last kRecent segments pulled, each with its start, its path and its
//     job number (the board runs a segment a bounded distance behind the
//     pull: its queue and the controller's credit);
//   - running totals: paths opened, segments and actions pulled, and the
//     time budget of the part pulled (cut length at the slowest feed, a
//     rapid across the extent, a pierce and the program's waits per path).
// The cycle calls through it: nothing here allocates after construction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "control/job_source.hpp"
#include "kerf/geom/segment.hpp"

namespace kerf::simulated {

// The run's give-up time from what has been pulled: at least 600 s, else
// three times every pulled path at its slowest feed with its travel and
// pierce, and the waits (the whole-job rule `kerf sim` had, on a prefix).
struct TimeBudget {
  double cut_feed_mm_min = 0, rapid_mm_min = 0, arc_ok_timeout_s = 0, pierce_delay_s = 0, operator_delay_s = 0;
  double cut_mm = 0, extent = 0, waits_s = 0, slowest_mm_min = 0;
  std::size_t paths = 0;
  void add_segment(const Segment<double>& s, double feed_mm_s);
  void add_action(const control::JobAction& a);
  double limit_s() const;
};

struct PulledSegment {
  std::size_t job = SIZE_MAX;  // its job segment number (SIZE_MAX: the slot is empty)
  std::size_t path = 0;
  Segment<double> segment{};
};

class WatchedJobSource final : public control::JobSource {
 public:
  static constexpr std::size_t kRecent = 4096;
  // Each newly pulled segment goes to `on_segment` as well (the plot), when set.
  WatchedJobSource(control::JobSource& inner, const TimeBudget& budget,
                   std::function<void(const PulledSegment&)> on_segment = {});

  control::JobId id() const override { return inner_.id(); }
  std::size_t segment_count() const override { return inner_.segment_count(); }
  std::size_t path_count() const override { return inner_.path_count(); }
  std::size_t max_moves() const override { return inner_.max_moves(); }
  control::SegmentPlace locate(std::size_t k) override;
  const control::PathHead* open(std::size_t p) override;
  control::Pull segment(std::size_t i, const hal::SegmentCommand*& out) override;
  const control::JobAction* action(std::size_t a) override;
  const control::JobAction* replay_output(std::size_t path, std::size_t i) override {
    return inner_.replay_output(path, i);
  }
  std::size_t first_action() const override { return inner_.first_action(); }
  const char* error() const override { return inner_.error(); }

  // Job segment k, if it is among the last kRecent pulled.
  const PulledSegment* recent(std::size_t k) const;
  std::size_t paths_opened() const { return paths_; }
  std::size_t segments_pulled() const { return pulled_; }  // distinct job segments
  const TimeBudget& budget() const { return budget_; }
  // Whether the source had nothing ready (a segment `later`, a path not
  // there yet) since the last call.
  bool take_behind() {
    const bool b = behind_;
    behind_ = false;
    return b;
  }

 private:
  control::JobSource& inner_;
  TimeBudget budget_;
  std::function<void(const PulledSegment&)> on_segment_;
  std::vector<PulledSegment> ring_;
  std::size_t path_ = 0, first_ = 0, paths_ = 0, pulled_ = 0, actions_ = 0;
  Vec2<double> head_start_{};
  bool behind_ = false;
  bool located_ = false;  // locate() gave the start of segment located_at_
  std::size_t located_at_ = 0;
  Vec2<double> located_start_{};
};

}  // namespace kerf::simulated
