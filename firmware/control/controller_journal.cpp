// The controller's journal records: queued to the JournalWriter's thread
// (control/journal_writer.hpp), or written in the cycle with journal_inline.
#include "control/controller.hpp"
#include "control/format_text.hpp"

namespace kerf::control {

bool Controller::journal_completed(std::uint32_t k) {
  if (!writer_) return journal_->completed(k);
  if (writer_->completed(k)) return true;
  // Full: the record goes in from the reserve, and the run stops.
  journal_full_ = writer_->completed(k, true);
  return false;
}

void Controller::journal_cut_to(const CutPoint& p, bool urgent) {
  if (!writer_) {
    journal_->cut_to(p);  // a failed slot write is not fatal: the next one overwrites it
    return;
  }
  if (writer_->cut_to(p, urgent)) return;
  journal_full_ = true;  // a later cut point (the stop's, urgent) replaces this one
  journal_failed_ = true;
}

bool Controller::journal_finished() {
  if (!writer_) return journal_->finished();
  if (writer_->finished()) return true;
  journal_full_ = writer_->finished();  // cannot be full twice in a row unless the writer is stalled
  return false;
}

bool Controller::journal_lagging() const {
  if (!writer_ || writer_abandoned_ || writer_->failed()) return false;
  return finished_ ? !writer_->caught_up() : writer_->queued() > writer_->capacity() / 2;
}

std::string Controller::journal_error() const {
  if (journal_full_)
    return format_text("journal: the writer's queue is full (%zu records not yet on disk): the disk is stalled or "
                       "too slow; what is queued is still written",
                       writer_ ? writer_->queued() : std::size_t{0});
  if (writer_ && writer_->failed()) return std::string("journal: ") + writer_->last_error();
  return std::string("journal: ") + journal_->last_error();
}

void Controller::settle_journal() {
  if (!writer_ || writer_abandoned_) return;
  if (finished_at_ == WallClock::time_point{}) finished_at_ = WallClock::now();
  const bool failed = writer_->failed();
  if (!failed && writer_->caught_up()) {
    writer_->close();
    writer_.reset();
    return;
  }
  const double waited = std::chrono::duration<double>(WallClock::now() - finished_at_).count();
  if (!failed && waited < cfg_.journal_drain_timeout_s) return;
  // The progress on disk is what counts.
  report_.last_completed = writer_->synced_last();
  if (report_.has_cut_to && report_.cut_to.segment != report_.last_completed + 1) report_.has_cut_to = false;
  if (report_.state == State::done || report_.reason.empty()) {
    report_.state = state_ = State::fault;
    report_.reason = failed ? journal_error()
                            : format_text("journal: %zu records not on disk after %g s", writer_->queued(),
                                          cfg_.journal_drain_timeout_s);
  }
  if (failed) {
    writer_->close();
    writer_.reset();
  } else {
    writer_abandoned_ = true;  // the destructor waits for it
  }
}

}  // namespace kerf::control
