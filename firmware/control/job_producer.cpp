#include "control/job_producer.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

#include "control/cut_rules.hpp"
#include "control/soft_limits.hpp"

namespace kerf::control {

namespace {

bool has(const std::vector<int>& numbers, int n) { return std::find(numbers.begin(), numbers.end(), n) != numbers.end(); }

}  // namespace

JobProducer::~JobProducer() { stop(); }

void JobProducer::stop() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
}

void JobProducer::start(std::unique_ptr<job::ProgramStream> program, std::unique_ptr<PointPaths> points,
                        const StreamedJobSetup& setup, JobItemRing& ring, bool quiet) {
  program_ = std::move(program);
  points_ = std::move(points);
  file_ = program_ ? program_->summary().points.file : points_->file();
  setup_ = setup;
  fit_ = {setup.criterion, setup.numeric, setup.tol, setup.feed_mm_s, setup.max_feed_mm_s};
  if (points_ != nullptr) fit_.max_feed_mm_s = 1e300;  // a point file's paths run at the cut feed, as fit_paths_or_say's
  ring_ = &ring;
  quiet_ = quiet;
  totals_.gcode = program_ != nullptr;
  if (program_) {  // known before the first item: a stopped run's report says it too
    totals_.summary.points.file = file_;
    totals_.summary.dry_run = program_->dry_run();
  }
  thread_ = std::thread([this] { run(); });
}

StreamTotals JobProducer::totals() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return totals_;
}

const std::string& JobProducer::file() const { return file_; }

bool JobProducer::put(const JobItem& item) {
  while (!ring_->try_push(item)) {
    if (stopping_) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return true;
}

bool JobProducer::fail(std::string error, int rc, std::string say) {
  error_ = std::move(error);
  say_ = say.empty() ? error_ : std::move(say);
  exit_code_ = rc;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    totals_.failed = true;
  }
  failed_.store(true, std::memory_order_release);
  JobItem item;
  item.kind = JobItem::Kind::error;
  put(item);
  ring_->close();
  return false;
}

void JobProducer::run() {
  if (points_ != nullptr) {
    const job::ProgramPath pp;  // a point file's path: torch on, the cut feed, the fit's tol
    io::PointFile one;
    while (!stopping_) {
      const PointPaths::Next n = points_->next(one);
      if (n == PointPaths::Next::end) break;
      if (n == PointPaths::Next::error) {
        fail(points_->error(), 2);
        return;
      }
      if (!path(one, {}, pp)) return;
    }
    if (!stopping_) finish();
    return;
  }
  job::ProgramPiece piece;
  job::ProgramAction a;
  while (!stopping_) {
    switch (program_->next(piece, a)) {
      case job::ProgramStream::Next::action:
        if (!action(a)) return;
        break;
      case job::ProgramStream::Next::path: {
        io::PointFile one;
        one.file = file();
        one.points = std::move(piece.points);
        one.point_lines = std::move(piece.lines);
        if (!path(one, piece.feed, piece.path)) return;
        break;
      }
      case job::ProgramStream::Next::end: finish(); return;
      case job::ProgramStream::Next::error: fail(program_->error(), 2); return;
    }
  }
}

bool JobProducer::action(job::ProgramAction a) {
  if (setup_.io) {  // machine_can_run, one action at a time
    const std::string why = cannot_run(a, *setup_.io);
    if (!why.empty()) return fail(file() + ":" + std::to_string(a.line) + ": " + why, 2);
    if (a.kind == job::CanonKind::analog_out &&
        std::none_of(ignored_analog_.begin(), ignored_analog_.end(), [&](const auto& n) { return n.first == a.index; }))
      ignored_analog_.emplace_back(a.index, a.line);
  }
  // --dry-run: the outputs that would switch on (gas) are dropped (hold_outputs_off).
  if (setup_.outputs_off && (a.kind == job::CanonKind::digital_out || a.kind == job::CanonKind::analog_out) &&
      a.value != 0)
    return true;
  if (pending_.size() >= StreamJobSource::kActions)
    return fail(file() + ":" + std::to_string(a.line) + ": more than " + std::to_string(StreamJobSource::kActions) +
                    " actions between two paths: a streamed job holds no more",
                2);
  a.before_path = kept_;  // the paths before it that reach the job
  pending_.push_back(a);
  return true;
}

bool JobProducer::flush(bool last) {
  JobItem item;
  if (have_previous_) {
    if (last) after_.insert(after_.end(), carry_.begin(), carry_.end());
    if (after_.size() > StreamJobSource::kMaxMoves)
      return fail(file() + ": path " + std::to_string(kept_) + ": more than 1024 moves after it", 2);
    item.kind = JobItem::Kind::after;
    for (const hal::SegmentCommand& c : after_) {
      item.seg.cmd = c;
      if (!put(item)) return false;
    }
    item.kind = JobItem::Kind::path_end;
    if (!put(item)) return false;
  }
  item.kind = JobItem::Kind::action;
  for (const job::ProgramAction& a : pending_) {
    item.action = a;
    if (!put(item)) return false;
  }
  pending_.clear();
  return true;
}

bool JobProducer::path(const io::PointFile& one, const std::vector<double>& feed, const job::ProgramPath& pp) {
  const std::size_t p = program_paths_++;
  FittedJob f;
  std::string why;
  if (const int rc = fit_program_path(one, feed, pp, p, fit_, f, why); rc != 0)
    return fail(file() + ": " + why, rc, "kerf: " + file() + ": " + why);
  if (f.job.paths.empty()) {  // shorter than the grid: its moves go on with the next path
    append_moves(pp.before, fit_.max_feed_mm_s, carry_);
    append_moves(pp.after, fit_.max_feed_mm_s, carry_);
    return true;
  }
  CutPath& path = f.job.paths.front();
  path.before.insert(path.before.begin(), carry_.begin(), carry_.end());
  carry_.clear();
  std::vector<CutRuleNote> notes;
  if (setup_.rules) {
    notes = apply_cut_rules(f, *setup_.rules);
    for (CutRuleNote& n : notes) n.path = kept_;
    if (!quiet_) say_cut_rules(file(), notes, *setup_.rules);
  }
  if (setup_.limits && !check_soft_limits(f, one, *setup_.limits, nullptr, why, kept_)) return fail(why, 2);
  if (setup_.torch_off) {  // a bench or a dry run (hold_outputs_off)
    path.torch = false;
    for (hal::SegmentCommand& c : path.segments) c.torch = false;
  }
  if (path.before.size() > StreamJobSource::kMaxMoves)
    return fail(file() + ": path " + std::to_string(kept_ + 1) + ": more than 1024 moves before it", 2);
  if (!flush(false)) return false;
  JobItem item;
  item.kind = JobItem::Kind::head;
  item.moves = static_cast<std::uint32_t>(path.before.size());
  item.torch = path.torch;
  item.pierce_delay_s = path.pierce_delay_s;
  item.seg.from = path.start;
  if (!put(item)) return false;
  item.kind = JobItem::Kind::before;
  for (const hal::SegmentCommand& c : path.before) {
    item.seg.cmd = c;
    if (!put(item)) return false;
  }
  item.kind = JobItem::Kind::segment;
  Vec2<double> from = path.start;
  for (std::size_t k = 0; k < path.segments.size(); ++k) {
    item.seg.cmd = path.segments[k];
    item.seg.piece = f.pieces[k];
    item.seg.from = from;
    from = path.segments[k].end;
    if (!put(item)) return false;
  }
  after_ = std::move(path.after);
  have_previous_ = true;
  ++kept_;
  const std::lock_guard<std::mutex> lock(mutex_);
  ++totals_.paths;
  totals_.segments += path.segments.size();
  totals_.lines_for_arcs += f.lines_for_arcs;
  totals_.forced_commits += f.job.forced_commits;
  totals_.cut_rules.insert(totals_.cut_rules.end(), notes.begin(), notes.end());
  return true;
}

bool JobProducer::finish() {
  if (kept_ == 0) {
    const std::string why = "every path is shorter than the link's resolution (0.001 mm)";
    return fail(file() + ": " + why, 2, "kerf: " + file() + ": " + why);
  }
  job::GcodeProgram summary;
  if (program_) {
    summary = program_->summary();
    if (setup_.io) {  // machine_can_run's analog inputs, and its notes of the ignored numbers
      for (const auto& [n, line] : summary.interp.analog_inputs)
        if (!has(setup_.io->analog_ignore, n)) {
          const std::string k = std::to_string(n);
          return fail(file() + ":" + std::to_string(line) + ": analog input " + k + " (M66 E" + k +
                          "): kerf has no analog lines: add " + k + " to [analog] ignore to run the program without it",
                      2);
        }
      auto note = [&](const char* what, int n, std::size_t line) {
        const std::string text = std::string(what) + " " + std::to_string(n) +
                                 " ignored ([analog] ignore), first at line " + std::to_string(line);
        if (std::find(summary.interp.notes.begin(), summary.interp.notes.end(), text) == summary.interp.notes.end())
          summary.interp.notes.push_back(text);
      };
      for (const auto& [n, line] : ignored_analog_) note("analog output", n, line);
      for (const auto& [n, line] : summary.interp.analog_inputs) note("analog input", n, line);
    }
  }
  if (!flush(true)) return false;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    totals_.summary = std::move(summary);
    totals_.ended = true;
  }
  JobItem item;
  item.kind = JobItem::Kind::end;
  if (!put(item)) return false;
  ended_.store(true, std::memory_order_release);
  ring_->close();
  return true;
}

}  // namespace kerf::control
