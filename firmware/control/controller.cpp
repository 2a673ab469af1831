#include "control/controller.hpp"

#include <algorithm>
#include <cstdio>

#include "control/format_text.hpp"
#include "kerf/core/assert.hpp"

namespace kerf::control {

const char* to_string(State s) {
  switch (s) {
    case State::idle: return "idle";
    case State::ready: return "ready";
    case State::travel: return "travel";
    case State::piercing: return "piercing";
    case State::cutting: return "cutting";
    case State::feed_hold: return "feed-hold";
    case State::done: return "done";
    case State::fault: return "fault";
    case State::estop: return "estop";
    case State::action: return "action";
  }
  return "unknown";
}

namespace {

// Closer than this the board has nothing to move (1 nm; a count is 1 um or more).
constexpr double kSamePoint = 1e-6;

bool transient(hal::LinkError e) {
  return e == hal::LinkError::timeout || e == hal::LinkError::disconnected ||
         e == hal::LinkError::malformed || e == hal::LinkError::busy;
}

std::string board_fault_text(std::uint16_t bits) {
  std::string s = "board fault:";
  if (bits & hal::kFaultAbort) s += " abort";
  if (bits & hal::kFaultLinkWatchdog) s += " link-watchdog";
  if (bits & hal::kFaultBadSegment) s += " bad-segment";
  if (bits & hal::kFaultStarved) s += " starved";
  if (bits & hal::kFaultDrive) s += " drive-fault";
  if (bits & hal::kFaultSoftLimit) s += " soft-limit (a segment outside the axes' min/max)";
  char hex[24];
  std::snprintf(hex, sizeof hex, " (bits 0x%04x)", static_cast<unsigned>(bits));
  return s + hex;
}

}  // namespace

Controller::Controller(JobSource& job, const ControllerConfig& cfg, hal::SegmentLink& link, hal::Gpio& gpio,
                       Journal* journal)
    : job_(job), cfg_(cfg), link_(link), gpio_(gpio), journal_(journal),
      actions_(job, cfg.outputs, cfg.operator_delay_s), latch_(cfg.reset_at_start), ferror_(cfg.ferror) {}

Controller::Controller(const Job& job, const ControllerConfig& cfg, hal::SegmentLink& link, hal::Gpio& gpio,
                       Journal* journal)
    : owned_(std::make_unique<WholeJobSource>(job)), job_(*owned_), cfg_(cfg), link_(link), gpio_(gpio),
      journal_(journal), actions_(*owned_, cfg.outputs, cfg.operator_delay_s), latch_(cfg.reset_at_start),
      ferror_(cfg.ferror) {}

Controller::~Controller() = default;  // the writer's destructor writes what is queued

void Controller::start(const ResumePoint& from) {
  const std::size_t n = job_.segment_count();  // JobSource::kUnknownCount for a stream not yet ended
  // The writer thread from the first start on (a restart after a reset keeps it).
  const bool journal_done = journal_ != nullptr && writer_ == nullptr && journal_->state().finished;
  if (journal_ && !cfg_.journal_inline && !writer_) writer_ = std::make_unique<JournalWriter>(*journal_, cfg_.journal_queue);
  finished_at_ = {};
  report_ = RunReport{};
  report_.planned = n;
  report_.first = from.first;
  report_.last_completed = static_cast<std::int64_t>(from.first) - 1;
  finished_ = false;
  have_status_ = false;
  has_tail_ = false;
  // The longest queue_ holds: the moves before a path and its travel, the
  // moves after it, or a resumed segment's rest (resume_segment.hpp). A
  // path's segments are not queued: pump() takes them from the source.
  queue_.clear();
  queue_.reserve(job_.max_moves() + 2);
  job_of_wire_.assign(kWireWindow, -1);
  next_seg_ = from.first;
  pierce_at_ = from.from;
  state_ = State::ready;
  if (from.done || n == 0) {
    state_ = State::done;
    finished_ = true;
    if (journal_ && !journal_done) journal_finished();
    return;
  }
  // Resumed inside a segment: its rest on the link's grid, by the fit's
  // contract (control/resume_segment.hpp). At (within a count of) or past its
  // end it was cut whole; record it and start at the next one.
  resumed_.clear();
  queue_extra_ = 0;
  opening_ = false;
  SegmentPlace at = job_.locate(next_seg_);
  if (distance(from.from, at.start) > kSamePoint) {
    resumed_ = resume_segment(at.segment, at.start, from.from);
    pierce_at_ = resumed_.from;
  }
  if (resumed_.whole || distance(from.from, at.segment.end) < kSamePoint) {
    resumed_.clear();
    if (journal_) journal_completed(static_cast<std::uint32_t>(next_seg_));
    report_.last_completed = static_cast<std::int64_t>(next_seg_);
    ++report_.completed_this_run;
    ++next_seg_;
    if (next_seg_ < job_.segment_count()) at = job_.locate(next_seg_);  // a stream may meet its end there
    if (next_seg_ >= job_.segment_count()) {
      state_ = State::done;
      finished_ = true;
      if (journal_) journal_finished();
      return;
    }
    pierce_at_ = at.start;
  }
  path_ = at.path;
  head_ = job_.open(path_);  // locate() made it available
  KERF_ASSERT(head_ != nullptr && "a located path opens");
  // Resumed: the outputs the program set before this path are set again;
  // its dwells, pauses and waits are not run again. The actions just
  // before the path run only when nothing of it was cut (control/README.md).
  first_actions_ = at.index == 0 && distance(pierce_at_, head_->start) < kSamePoint;
  if (!actions_.replay_outputs(first_actions_ ? path_ : path_ + 1) && stop_request_.empty())
    stop_request_ = actions_.error();  // a fault in the first cycle, before anything moves
  if (*job_.error() != '\0' && stop_request_.empty()) stop_request_ = std::string("job: ") + job_.error();  // locate() failed
  report_.actions.reserve(ActionRunner::kLogged);  // as the runner's log: copying it never allocates
}

void Controller::cycle(double now_s) {
  if (finished_) {
    settle_journal();
    return;
  }
  cycle_steps(now_s);
  drive_thc_lock();
}

void Controller::cycle_steps(double now_s) {
  // Inputs first, and the torch off before any link I/O when they trip.
  hal::GpioInputs in;
  std::string trip;
  State trip_state = State::fault;
  const bool inputs_read = gpio_.read(now_s, in);
  if (!inputs_read) {
    trip = std::string("gpio: ") + gpio_.last_error();
  } else {
    prev_in_ = in_;
    in_ = in;
    if (in.estop) {
      trip = "E-stop";
      trip_state = State::estop;
    } else if (!stop_request_.empty()) {
      trip = stop_request_;
    } else if (in.any_limit()) {
      for (std::uint8_t i = 0; i < in.limit_count; ++i)
        if (in.limit[i]) {
          trip = format_text("limit switch %u hit", static_cast<unsigned>(i));
          break;
        }
    }
  }
  if (latch_cycle(now_s, inputs_read)) return;  // latched at rest: waiting for a reset
  const bool stopping = state_ == State::fault || state_ == State::estop;
  const bool cut_was_on = torch_;
  if (!trip.empty() && !stopping && torch_) set_torch(false, now_s);
  const bool fresh = poll_link(now_s);
  if (stopping || state_ == State::fault || state_ == State::estop) {
    // Waiting for the board to come to rest (or for the link to be given up).
    const bool link_gone =
        link_down_ && std::chrono::duration<double>(WallClock::now() - link_down_since_).count() >= cfg_.link_timeout_s;
    if ((fresh && at_rest_) || (!fresh && link_gone)) {
      report_.stopped_at = st_.position;
      park_or_finish();
    }
    return;
  }
  if (fresh) record_completions();
  if (!trip.empty()) {
    if (cut_was_on && fresh) torch_went_off();  // the torch went off above, before the link I/O
    stop(trip_state, trip, now_s);
    return;
  }
  if (!fresh || state_ == State::fault) return;
  if (following_error_fault(now_s)) return;
  if (st_.state == hal::BoardState::fault && state_ != State::ready) {
    stop(State::fault, board_fault_text(st_.faults), now_s);
    return;
  }
  run_state(now_s);
}

bool Controller::link_ok(hal::LinkError e) {
  if (e == hal::LinkError::none) {
    link_down_ = false;
    return true;
  }
  ++report_.link_errors;
  if (!link_down_) {
    link_down_ = true;
    link_down_since_ = WallClock::now();
  }
  return false;
}

bool Controller::poll_link(double now_s) {
  hal::BoardStatus s;
  const hal::LinkError e = link_.status(s);
  if (!link_ok(e)) {
    const double down = std::chrono::duration<double>(WallClock::now() - link_down_since_).count();
    if (state_ == State::fault || state_ == State::estop) return false;
    if (!transient(e)) {
      stop(State::fault, std::string("link: ") + link_.last_error(), now_s);
    } else {
      // The board stops by itself after its watchdog time: so does the torch.
      if (down >= cfg_.link_watchdog_s && torch_) {
        set_torch(false, now_s);
        report_.torch_off_valid = true;
        report_.torch_off_at = st_.position;
      }
      if (down >= cfg_.link_timeout_s)
        stop(State::fault,
             format_text("link down for more than %g s: ", cfg_.link_timeout_s) + link_.last_error(), now_s);
    }
    return false;
  }
  // At rest: the same position over three polls while not running a queue.
  if (have_status_ && s.position == st_.position && s.z == st_.z && s.state != hal::BoardState::running)
    ++rest_polls_;
  else
    rest_polls_ = 0;
  at_rest_ = rest_polls_ >= 2 || s.state == hal::BoardState::done || s.state == hal::BoardState::idle;
  st_ = s;
  report_.final_z = s.z;
  have_status_ = true;
  return true;
}

void Controller::record_completions() {
  while (seen_executed_ < st_.last_executed) {
    ++seen_executed_;
    const std::int64_t k = job_segment_of(seen_executed_);
    if (k < 0 || !completes_job_segment(seen_executed_)) continue;
    const bool journalled = journal_ == nullptr || journal_completed(static_cast<std::uint32_t>(k));
    if (!journalled && !journal_full_) {  // not written: not counted
      journal_failed_ = true;
      return;
    }
    report_.last_completed = k;  // queued (a full queue still took it from its reserve)
    report_.has_cut_to = false;
    ++report_.completed_this_run;
    if (!journalled) {
      journal_failed_ = true;
      return;
    }
  }
}

void Controller::record_cut_to() {
  if (torch_) record_cut_point();
}

void Controller::record_cut_point(bool urgent) {
  const std::int64_t k = job_segment_of(st_.executing);
  if (k < 0 || k != report_.last_completed + 1) return;
  report_.has_cut_to = true;
  report_.cut_to = {static_cast<std::uint32_t>(k), st_.position};
  if (journal_) journal_cut_to(report_.cut_to, urgent);
}

void Controller::torch_went_off() {
  record_cut_point(true);  // the cut ends where the torch goes off: from the queue's reserve if need be
  report_.torch_off_valid = true;
  report_.torch_off_at = st_.position;
}

bool Controller::set_torch(bool on, double now_s) {
  torch_ = on;
  if (gpio_.set_torch(on)) return true;
  // An output that cannot be switched is a fault; off is retried every cycle.
  if (on) stop(State::fault, std::string("gpio: cannot switch the torch on: ") + gpio_.last_error(), now_s);
  return false;
}

void Controller::stop(State s, const std::string& why, double now_s) {
  if (state_ == State::fault || state_ == State::estop) return;
  latch_.trip();
  if (torch_) {
    torch_went_off();
    torch_ = false;
    gpio_.set_torch(false);
  }
  if (cfg_.outputs != nullptr) cfg_.outputs->all_off();  // the program's outputs go safe with the torch
  link_.command(hal::Command::abort);  // brake on the path, drop the queue; the link may be down
  state_ = s;
  report_.state = s;
  report_.reason = why;
  report_.reason_t_s = now_s;
  rest_polls_ = 0;
  at_rest_ = false;
}

void Controller::begin_travel(Vec2<double> to) {
  block_ = Block::rapid;
  queue_.clear();
  sent_ = 0;
  started_ = finish_sent_ = false;
  after_path_ = false;
  // From the end of the last segment sent (exact), not the board's position
  // (rounded to counts): a path that starts where the last one ended needs
  // no travel, and a travel a fraction of a count long would be empty on the board.
  Vec2<double> at = has_tail_ ? tail_ : st_.position;
  if (path_ < job_.path_count()) queue_moves(*head_->before, at);
  if (distance(at, to) > kSamePoint) {
    hal::SegmentCommand c;
    c.kind = SegmentKind::line;
    c.end = to;
    c.feed = cfg_.rapid_feed_mm_s;
    c.torch = false;
    queue_.push_back(c);
  }
  state_ = State::travel;
}

void Controller::queue_moves(const std::vector<hal::SegmentCommand>& moves, Vec2<double>& at) {
  for (hal::SegmentCommand c : moves) {
    if (c.z_move) {
      c.end = at;  // Z alone, where the axes stand
    } else if (distance(at, c.end) <= kSamePoint) {
      continue;
    }
    c.torch = false;
    if (!(c.feed > 0)) c.feed = cfg_.rapid_feed_mm_s;  // a rapid (a z move's is capped by the z axis)
    at = c.end;
    queue_.push_back(c);
  }
}

void Controller::begin_pierce(double now_s) {
  if (!head_->torch) {  // a dry-run path: no torch, no pierce
    state_ = State::cutting;
    if (!resume_after_pierce_) {
      begin_cut();
      pump();
    } else if (link_ok(link_.command(hal::Command::resume))) {
      resume_after_pierce_ = false;
    }
    return;
  }
  state_ = State::piercing;
  arc_ok_t_ = -1.0;
  torch_on_t_ = now_s;
  ++report_.pierces;
  set_torch(true, now_s);
}

void Controller::begin_cut() {
  block_ = Block::cut;
  queue_.clear();
  std::size_t i = next_seg_ - head_->first_segment;
  queue_extra_ = 0;
  if (resumed_.count > 0) {  // the first segment's rest, from the resume point
    for (int k = 0; k < resumed_.count; ++k) queue_.push_back(resumed_.segments[k]);
    queue_extra_ = static_cast<std::size_t>(resumed_.count - 1);
    resumed_.clear();
    ++i;
  }
  path_next_ = i;
  path_ended_ = false;
  pulled_ = nullptr;
  sent_ = 0;
  started_ = finish_sent_ = false;
  state_ = State::cutting;
}

bool Controller::pump() {
  const hal::SegmentCommand* next = nullptr;
  while (st_.credit > 0 && next_seq_ < seen_executed_ + kWireWindow && (next = next_wire()) != nullptr) {
    if (!started_) {  // the block's first segment
      if (!link_ok(link_.command(hal::Command::start))) return false;
      started_ = true;
    }
    hal::SegmentCommand c = *next;
    c.seq = next_seq_ + 1;
    hal::BoardStatus s;
    if (!link_ok(link_.push(c, s))) return false;  // the same number goes again next cycle
    st_ = s;
    tail_ = c.end;
    has_tail_ = true;
    ++next_seq_;
    if (c.z_move) ++report_.z_moves;
    job_of_wire_[next_seq_ % kWireWindow] = block_ == Block::cut ? wire_job(sent_) : -1;
    block_last_seq_ = next_seq_;
    if (sent_ >= queue_.size()) {
      ++path_next_;
      pulled_ = nullptr;
    }
    ++sent_;
  }
  if (block_ == Block::cut && !path_ended_ && sent_ >= queue_.size()) next_wire();  // learns the path's end
  if (block_sent() && sent_ > 0 && !finish_sent_) {
    if (!link_ok(link_.command(hal::Command::finish))) return false;
    finish_sent_ = true;
  }
  return true;
}

bool Controller::block_done() const {
  if (sent_ == 0 && block_sent()) return true;  // nothing to move
  return finish_sent_ && st_.state == hal::BoardState::done && st_.last_executed >= block_last_seq_;
}

void Controller::path_finished(double now_s) {
  set_torch(false, now_s);
  next_seg_ += sent_ - queue_extra_;
  queue_extra_ = 0;
  const std::vector<hal::SegmentCommand>& after = *head_->after;  // valid until the next open()
  ++path_;
  head_ = nullptr;
  if (!after.empty()) {  // z axis: the retract and what else follows the path, then its actions
    block_ = Block::rapid;
    queue_.clear();
    sent_ = 0;
    started_ = finish_sent_ = false;
    Vec2<double> at = tail_;
    queue_moves(after, at);
    after_path_ = true;
    state_ = State::travel;
    return;
  }
  run_actions_or_travel(now_s);
}

void Controller::run_state(double now_s) {
  if (journal_failed_ || (writer_ && writer_->failed())) {
    journal_failed_ = true;
    stop(State::fault, journal_error(), now_s);
    return;
  }
  const bool hold_pressed = in_.hold && !prev_in_.hold;
  const bool start_pressed = in_.cycle_start && !prev_in_.cycle_start;
  switch (state_) {
    case State::idle:
    case State::done:
    case State::fault:
    case State::estop:
      return;
    case State::ready:
      // Take over the board: clear a fault a previous run left, then number
      // our segments after whatever it has already accepted.
      if (st_.state == hal::BoardState::fault) {
        link_ok(link_.command(hal::Command::fault_reset));
        return;
      }
      if (st_.state == hal::BoardState::running || st_.state == hal::BoardState::hold) {
        link_ok(link_.command(hal::Command::abort));
        return;
      }
      base_ = next_seq_ = seen_executed_ = st_.last_accepted;
      if (first_actions_) run_actions_or_travel(now_s);
      else begin_travel(pierce_at_);
      return;
    case State::action: {
      if (opening_) {
        run_actions_or_travel(now_s);
        return;
      }
      const bool done = actions_.step(now_s, start_pressed);
      if (!actions_.error().empty()) stop(State::fault, actions_.error(), now_s);  // an output or input failed
      else if (done) actions_done(now_s);
      return;
    }
    case State::travel:
      if (hold_pressed) {
        if (!queue_.empty() && link_ok(link_.command(hal::Command::hold))) {
          held_from_ = State::travel;
          state_ = State::feed_hold;
        }
        return;
      }
      if (pump() && block_done()) {
        if (!after_path_) begin_pierce(now_s);
        else run_actions_or_travel(now_s);
      }
      return;
    case State::piercing:
      if (hold_pressed) {
        set_torch(false, now_s);
        held_from_ = State::piercing;
        state_ = State::feed_hold;
        return;
      }
      if (!in_.arc_ok) {
        if (arc_ok_t_ >= 0.0) {
          stop(State::fault, format_text("arc-OK lost during the pierce at (%.3f, %.3f)", pierce_at_.x, pierce_at_.y),
               now_s);
        } else if (now_s - torch_on_t_ > cfg_.arc_ok_timeout_s) {
          stop(State::fault,
               format_text("no arc-OK within %g s of torch on at the pierce at (%.3f, %.3f)", cfg_.arc_ok_timeout_s,
                      pierce_at_.x, pierce_at_.y),
               now_s);
        }
        return;
      }
      if (arc_ok_t_ < 0.0) arc_ok_t_ = now_s;
      if (now_s - arc_ok_t_ < pierce_delay()) return;
      if (resume_after_pierce_) {
        if (link_ok(link_.command(hal::Command::resume))) {
          resume_after_pierce_ = false;
          state_ = State::cutting;
        }
      } else {
        begin_cut();
        pump();
      }
      return;
    case State::cutting:
      if (resume_after_pierce_) {  // a dry-run path held: the resume command failed last cycle
        if (link_ok(link_.command(hal::Command::resume))) resume_after_pierce_ = false;
        return;
      }
      if (torch_ && !in_.arc_ok) {
        stop(State::fault,
             format_text("arc-OK lost while cutting segment %lld", static_cast<long long>(report_.last_completed + 1)),
             now_s);
        return;
      }
      record_cut_to();
      if (hold_pressed) {
        if (link_ok(link_.command(hal::Command::hold))) {
          held_from_ = State::cutting;
          hold_braking_ = true;
          state_ = State::feed_hold;
        }
        return;
      }
      if (pump() && block_done()) path_finished(now_s);
      return;
    case State::feed_hold:
      if (held_from_ == State::cutting && hold_braking_) {
        // The cut goes on while the axes brake; the torch goes off once they stop.
        if (torch_ && !in_.arc_ok) {
          stop(State::fault, "arc-OK lost during a feed hold", now_s);
          return;
        }
        record_cut_to();
        if (at_rest_) {
          set_torch(false, now_s);
          hold_braking_ = false;
          pierce_at_ = st_.position;
        }
        return;
      }
      if (!start_pressed) return;
      if (held_from_ == State::travel) {
        if (link_ok(link_.command(hal::Command::resume))) state_ = State::travel;
      } else {
        // Held while cutting (or while re-piercing after that): the board
        // holds the rest of the path, so the pierce ends in a resume.
        if (held_from_ == State::cutting) resume_after_pierce_ = true;
        begin_pierce(now_s);
      }
      return;
  }
}

}  // namespace kerf::control
