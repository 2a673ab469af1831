#include "control/job_time.hpp"

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "kerf/motion/board_executor.hpp"
#include "kerf/motion/interpolator_motion.hpp"

namespace kerf::control {

namespace {

using Board = motion::BoardExecutor<double, motion::InterpolatorMotion<double>>;

// The board, fed one block at a time as the controller does.
class BoardModel {
 public:
  explicit BoardModel(const JobTimeSettings& s)
      : s_(s), slots_(s.lookahead), queue_(s.board_queue), stage_({slots_.data(), slots_.size()}) {
    motion::MotionConfig<double> c;
    c.period = s.servo_period_s;
    c.accel = s.accel_mm_s2;
    c.vad = s.vad;
    c.counts_per_mm = {s.counts_per_mm, s.counts_per_mm};
    ok_ = stage_.configure(c) == Status::ok;
    board_.emplace(stage_, Span<motion::BoardSegment<double>>(queue_.data(), queue_.size()), s.start);
    if (s.z.configured()) board_->configure_z(s.z, 0.0);
  }
  bool ok() const { return ok_; }

  // Servo periods from the start command to done.
  double run(const std::vector<hal::SegmentCommand>& block) {
    std::size_t sent = 0;
    long ticks = 0;
    board_->command(hal::Command::start);
    for (;;) {
      while (sent < block.size()) {
        hal::SegmentCommand c = block[sent];
        c.seq = ++seq_;
        if (board_->accept(c) != motion::BoardAccept::queued) {
          --seq_;
          break;
        }
        ++sent;
      }
      if (sent == block.size()) board_->command(hal::Command::finish);
      board_->step();
      ++ticks;
      if (board_->state() == hal::BoardState::done) break;
      if (board_->state() == hal::BoardState::fault) {
        ok_ = false;
        break;
      }
    }
    return static_cast<double>(ticks) * s_.servo_period_s;
  }

 private:
  const JobTimeSettings& s_;
  std::vector<motion::QueuedSegment<double>> slots_;
  std::vector<motion::BoardSegment<double>> queue_;
  motion::InterpolatorMotion<double> stage_;
  std::optional<Board> board_;
  std::uint32_t seq_ = 0;
  bool ok_ = true;
};

}  // namespace

JobTime estimate_job_time(const Job& job, const JobTimeSettings& s) {
  JobTime t;
  BoardModel board(s);
  // Each wait ends at the first controller cycle at or after it.
  const auto cycles = [&](double seconds) { return std::ceil(seconds / s.cycle_s - 1e-9) * s.cycle_s; };
  const auto actions_before = [&](std::size_t path) {
    for (const JobAction& a : job.actions) {
      if (a.before_path != path) continue;
      if (a.kind == job::CanonKind::dwell) t.actions_s += cycles(a.value);
      else if (a.kind == job::CanonKind::pause) t.actions_s += cycles(s.operator_delay_s);
      else if (a.kind == job::CanonKind::wait_input && a.mode >= 1 && a.mode <= 3) t.actions_s += cycles(a.value);
    }
  };
  Vec2<double> at = s.start;
  // The moves a z axis adds before and after a path, as the controller sends them.
  const auto moves = [&](const std::vector<hal::SegmentCommand>& list, std::vector<hal::SegmentCommand>& block) {
    for (hal::SegmentCommand c : list) {
      if (c.z_move) c.end = at;
      else if (distance(at, c.end) <= 1e-6) continue;
      c.torch = false;
      if (!(c.feed > 0)) c.feed = s.rapid_feed_mm_s;
      at = c.end;
      block.push_back(c);
    }
  };
  for (std::size_t p = 0; p < job.paths.size(); ++p) {
    const CutPath& path = job.paths[p];
    actions_before(p);
    std::vector<hal::SegmentCommand> travel;
    moves(path.before, travel);
    if (distance(at, path.start) > 1e-6) {
      hal::SegmentCommand rapid;
      rapid.end = path.start;
      rapid.feed = s.rapid_feed_mm_s;
      rapid.torch = false;
      travel.push_back(rapid);
    }
    if (!travel.empty()) t.travel_s += cycles(board.run(travel));
    if (path.torch) {
      ++t.pierces;
      t.pierce_s += cycles(s.arc_ok_s) + cycles(path.pierce_delay_s >= 0 ? path.pierce_delay_s : s.pierce_delay_s);
    }
    t.cut_s += cycles(board.run(path.segments)) + s.cycle_s;
    at = path.segments.empty() ? path.start : path.segments.back().end;
    std::vector<hal::SegmentCommand> after;
    moves(path.after, after);
    if (!after.empty()) t.travel_s += cycles(board.run(after));
  }
  actions_before(job.paths.size());
  t.ok = board.ok();
  // Taking the board over at the start, and the axes seen at rest at the end.
  t.actions_s += 5 * s.cycle_s;
  t.total_s = t.cut_s + t.travel_s + t.pierce_s + t.actions_s;
  return t;
}

}  // namespace kerf::control
