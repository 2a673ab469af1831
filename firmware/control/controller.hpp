// The machine controller: runs a job (a JobSource: control/job_source.hpp,
// read path by path and segment by segment, never whole) on a motion board (hal::SegmentLink)
// with the torch and the safety inputs on hal::Gpio, one cycle at a time.
//
//   Idle -> Ready -> Travel -> Piercing -> Cutting <-> FeedHold ... -> Done
//   Fault and EStop from anywhere.
//
// Each cut path: a rapid to its pierce point with the torch off (Travel);
// torch on, wait for arc-OK (at most arc_ok_timeout), wait the pierce delay
// (Piercing); stream the path's segments at the cut feed (Cutting); torch off
// when the board has run the path's last segment. A feed hold brakes on the
// path, turns the torch off once stopped, and re-pierces there on cycle start.
//
// Faults (E-stop, a limit switch, arc-OK lost while cutting, no arc-OK at a
// pierce, a board/drive fault, the link down, a GPIO error) switch the torch
// off in the cycle they are seen, abort the board (it brakes to a stop on the
// path and drops its queue) and end the run with a reason. The journal keeps
// every completed segment and the point the torch went off at, so a resumed
// run re-pierces exactly there: nothing is cut twice, nothing is skipped.
//
// Safety (controller_safety.cpp): the E-stop chain is latched (SafetyLatch,
// LinuxCNC's estop_latch): nothing moves until a reset edge arrives with the
// E-stop clear, and after an E-stop or a fault the machine stays stopped
// until the next accepted reset. With a reset line (wait_for_reset) the
// controller then waits latched at rest and, on a reset, goes back to Ready
// and finishes the job from its cut point; without one the run ends. The
// following error (actual vs commanded position, FollowingError) is a fault.
//
// The controller never blocks: each cycle makes at most a few link
// transactions and returns. It allocates only in start() (and in a fault's
// reason text), and never waits on the disk: journal records go through a
// JournalWriter's queue to its thread (control/journal_writer.hpp); a full
// queue is a fault (torch off, motion stopped on the path, the refused record
// still written from the queue's reserve). A run finishes only once the
// writer has synced every record: the report's progress is what is on disk.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "control/job.hpp"
#include "control/job_actions.hpp"
#include "control/job_source.hpp"
#include "control/following_error.hpp"
#include "control/journal.hpp"
#include "control/journal_writer.hpp"
#include "control/resume_segment.hpp"
#include "control/safety_latch.hpp"
#include "kerf/hal/gpio.hpp"
#include "kerf/hal/segment_link.hpp"

namespace kerf::control {

// action: the program's actions between paths (dwell, pause, outputs, waits; control/job_actions.hpp).
enum class State : std::uint8_t { idle, ready, travel, piercing, cutting, feed_hold, done, fault, estop, action };
const char* to_string(State s);

struct ControllerConfig {
  double rapid_feed_mm_s = 10000.0 / 60.0;
  double pierce_delay_s = 0.5;
  double arc_ok_timeout_s = 3.0;
  // Link health runs on the wall clock (a stalled transaction takes wall
  // time whatever the simulation does). The board's watchdog stops it after
  // link_watchdog_s without a request: the torch goes off then; the run ends
  // in Fault once the link has been down for link_timeout_s.
  double link_watchdog_s = 0.5;
  double link_timeout_s = 1.0;
  // A pause (M0/M1) ends on cycle-start; >= 0: a simulated operator presses it this long after (kerf sim).
  double operator_delay_s = -1.0;
  // The program's outputs and inputs (M62..M68, M66; not owned); null: none.
  Outputs* outputs = nullptr;
  // The E-stop latch: the reset edge at start-up (kerf run --reset; the
  // simulator's operator), and whether a reset line exists (then a stop
  // waits latched for a reset instead of ending the run).
  bool reset_at_start = true;
  bool wait_for_reset = false;
  FerrorLimits ferror;  // machine.ferror, machine.min_ferror, max_feed
  // The journal: queued to a writer thread (records of capacity), or written
  // and synced in the cycle (journal_inline: the old way, for the benchmark).
  bool journal_inline = false;
  std::size_t journal_queue = JournalWriter::kDefaultCapacity;
  double journal_drain_timeout_s = 10.0;  // wall time the end of a run waits for the writer
};

struct RunReport {
  State state = State::idle;
  std::string reason;                 // why it stopped, when not done
  double reason_t_s = 0.0;            // controller time of the fault
  std::size_t planned = 0;            // segments in the job
  std::size_t first = 0;              // first segment of this run (resume)
  std::size_t completed_this_run = 0; // completion records this run wrote
  std::int64_t last_completed = -1;   // job segment index
  bool has_cut_to = false;            // where the torch went off inside the next segment
  CutPoint cut_to;
  bool torch_off_valid = false;
  Vec2<double> torch_off_at{};        // board position when the fault switched the torch off
  Vec2<double> stopped_at{};          // board position once at rest
  std::uint64_t link_errors = 0;      // failed transactions (each retried next cycle)
  std::uint32_t pierces = 0;
  std::uint32_t z_moves = 0;          // z moves sent this run (z axis)
  double final_z = 0;                 // mm, the board's z when the run ended
  std::vector<ActionEvent> actions;   // the program's actions run (dwell, pause, outputs, waits): the first ActionRunner::kLogged
  ActionCounts action_counts;         // all of them
  // Safety: the last refused reset, resets accepted, watchdog toggles, and
  // the following error (largest seen; at a following-error fault, the gap
  // and the limit then).
  std::string reset_refused;
  std::uint32_t resets = 0;
  std::uint32_t watchdog_toggles = 0;
  double max_ferror_mm = 0.0;
  double ferror_at_fault_mm = 0.0, ferror_limit_mm = 0.0;
};

class Controller {
 public:
  // The job as it streams (not owned; it must outlive the controller).
  Controller(JobSource& job, const ControllerConfig& cfg, hal::SegmentLink& link, hal::Gpio& gpio,
             Journal* journal);
  // A job held whole (through a WholeJobSource the controller owns).
  Controller(const Job& job, const ControllerConfig& cfg, hal::SegmentLink& link, hal::Gpio& gpio,
             Journal* journal);

  // Prepares a run from `from` (ResumePoint{} for a new job). Allocates
  // (a bounded amount: nothing grows with the job's length).
  void start(const ResumePoint& from);
  // One cycle at controller time now_s (monotonic; simulated in the simulator).
  void cycle(double now_s);
  ~Controller();
  // Stops the run in the next cycle as a fault with this reason (a signal,
  // the operator): torch off, motion stopped on the path, progress kept.
  void request_stop(const std::string& why) { stop_request_ = why; }

  State state() const { return state_; }
  // Done, or stopped by a fault with the board at rest: nothing more will happen.
  // Also waits for the journal writer to have synced everything.
  bool finished() const { return finished_ && (writer_ == nullptr || writer_abandoned_); }
  // The simulator's clock waits while this holds (its disk is not simulated):
  // the writer is behind by more than half its queue, or the run is over and
  // waits for it. False without a writer, or once it failed.
  bool journal_lagging() const;
  // The journal is the caller's to read: no writer thread is still at it (one
  // left behind a stalled disk after journal_drain_timeout_s still is).
  bool journal_settled() const { return writer_ == nullptr; }
  // The journal's writer while a run is on (tests hold it to fill its queue).
  JournalWriter* journal_writer() { return writer_.get(); }
  bool torch() const { return torch_; }
  bool link_down() const { return link_down_; }
  const RunReport& report() const { return report_; }
  // The job segment a board sequence number carries; -1 for a rapid or unknown
  // (and for one more than kWireWindow numbers behind the last sent).
  std::int64_t job_segment_of(std::uint32_t seq) const;
  // False for a rapid and for the first part of a resumed segment split in two.
  bool completes_job_segment(std::uint32_t seq) const;
  // Wire segments sent and not yet executed, at most (the board's queue is far shorter).
  static constexpr std::uint32_t kWireWindow = 1u << 14;

 private:
  enum class Block : std::uint8_t { none, rapid, cut };
  using WallClock = std::chrono::steady_clock;

  bool poll_link(double now_s);
  bool check_inputs(double now_s);
  void run_state(double now_s);
  void begin_travel(Vec2<double> to);
  void queue_moves(const std::vector<hal::SegmentCommand>& moves, Vec2<double>& at);  // z axis: CutPath before/after
  void begin_pierce(double now_s);
  void begin_cut();
  bool pump();  // sends what the board has room for; false on a link error
  // The block's next wire segment: queue_'s, then (a cut) the open path's; null: none now.
  const hal::SegmentCommand* next_wire();
  bool block_sent() const { return sent_ >= queue_.size() && (block_ != Block::cut || path_ended_); }
  std::int64_t wire_job(std::size_t block_index) const;  // job_of_wire_'s entry for the block's i-th
  bool wire_known(std::uint32_t seq) const { return seq > base_ && seq <= next_seq_ && next_seq_ - seq < kWireWindow; }
  bool open_path();  // head_ for path_ (false: the source has it not yet)
  bool block_done() const;
  void record_completions();
  void record_cut_to();     // while the torch is on: how far the cut has come
  void record_cut_point(bool urgent = false);  // the board's position on the running segment, to the journal
  void torch_went_off();    // the cut point and the report's torch-off position
  bool set_torch(bool on, double now_s);
  void stop(State s, const std::string& why, double now_s);
  void path_finished(double now_s);
  bool link_ok(hal::LinkError e);
  void run_actions_or_travel(double now_s);  // the actions before paths[path_], then its travel
  void actions_done(double now_s);
  void finish_job(double now_s);
  // The journal, through the writer when there is one (controller_journal.cpp).
  bool journal_completed(std::uint32_t k);
  void journal_cut_to(const CutPoint& p, bool urgent);
  bool journal_finished();
  std::string journal_error() const;
  void settle_journal();  // finished: wait for the writer, then close it
  double pierce_delay() const;
  // controller_safety.cpp
  void cycle_steps(double now_s);
  // gpio.thc_lock follows the board's thc_lock while the torch is on, off otherwise.
  void drive_thc_lock();
  bool latch_cycle(double now_s, bool inputs_read);  // true: this cycle is the latch's (parked)
  void park_or_finish();                             // stopped and at rest
  void restart_after_reset();
  bool following_error_fault(double now_s);

  std::unique_ptr<JobSource> owned_;  // the whole-job constructor's
  JobSource& job_;
  const PathHead* head_ = nullptr;  // the open path (path_)
  ControllerConfig cfg_;
  hal::SegmentLink& link_;
  hal::Gpio& gpio_;
  Journal* journal_;
  ActionRunner actions_;
  bool first_actions_ = true;  // run the actions before the first path (false: resumed inside it)

  State state_ = State::idle;
  bool finished_ = false;
  bool torch_ = false;
  bool thc_lock_out_ = false;  // what gpio.thc_lock was last driven to
  RunReport report_;
  hal::GpioInputs in_{}, prev_in_{};
  hal::BoardStatus st_{};
  Vec2<double> prev_pos_{};
  bool have_status_ = false, at_rest_ = false;
  int rest_polls_ = 0;
  bool journal_failed_ = false;
  bool journal_full_ = false;  // the writer's queue refused a record
  std::unique_ptr<JournalWriter> writer_;
  bool writer_abandoned_ = false;  // it did not catch up within journal_drain_timeout_s
  WallClock::time_point finished_at_{};
  std::string stop_request_;
  WallClock::time_point link_down_since_{};
  bool link_down_ = false;

  // Board sequence numbers: base_ + 1 is the first this run sends.
  std::uint32_t base_ = 0, next_seq_ = 0, seen_executed_ = 0;
  std::vector<std::int64_t> job_of_wire_;  // by seq % kWireWindow (wire_known)

  // The move being streamed: queue_ (a travel's moves, a resumed segment's
  // rest), then for a cut the open path's segments from path_next_ on.
  Block block_ = Block::none;
  std::vector<hal::SegmentCommand> queue_;
  std::size_t path_next_ = 0;  // the next segment of the open path to send
  bool path_ended_ = false;    // the source said the open path has no more
  const hal::SegmentCommand* pulled_ = nullptr;  // path_next_, from the source, not yet sent
  bool opening_ = false;       // waiting for the source's next path (State::action)
  std::size_t sent_ = 0;
  bool started_ = false, finish_sent_ = false;
  std::uint32_t block_last_seq_ = 0;
  std::size_t queue_extra_ = 0;  // wire segments beyond one for the queue's first job segment (resume split)
  ResumedSegment resumed_;       // the rest of the segment a run resumes inside, until its block is queued
  Vec2<double> tail_{};  // where the last segment sent ends
  bool has_tail_ = false;
  bool after_path_ = false;  // the travel block is the moves after a path (then its actions)

  // Where the job stands.
  std::size_t path_ = 0;        // current path
  std::size_t next_seg_ = 0;    // first job segment of the cut block to stream
  Vec2<double> pierce_at_{};
  double torch_on_t_ = 0.0, arc_ok_t_ = -1.0;
  bool resume_after_pierce_ = false;  // re-pierce after a hold: resume the board, no new block
  State held_from_ = State::idle;
  bool hold_braking_ = false;

  // Safety.
  SafetyLatch latch_;
  FollowingError ferror_;
  bool parked_ = true;          // latched and at rest, waiting for a reset (true until the first one)
  bool ran_ = false;            // the first reset came: a later one resumes the job
};

}  // namespace kerf::control
