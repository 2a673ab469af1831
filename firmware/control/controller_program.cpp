// The controller's steps between paths: the program's actions before the
// next path (control/job_actions.hpp), then its travel, or the job's end.
#include "control/controller.hpp"

namespace kerf::control {

bool Controller::open_path() {
  if (path_ >= job_.path_count() || head_ != nullptr) return true;  // past the last, or open (start())
  head_ = job_.open(path_);
  if (head_ == nullptr) {
    if (*job_.error() != '\0' && stop_request_.empty()) stop_request_ = std::string("job: ") + job_.error();
    return path_ >= job_.path_count();  // a stream that has just met its end: no path `path_`
  }
  pierce_at_ = head_->start;
  return true;
}

void Controller::run_actions_or_travel(double now_s) {
  // The next path from the source; a stream's producer may not have it yet:
  // wait at rest (State::action, opening_) and ask again each cycle.
  opening_ = !open_path();
  if (opening_) {
    state_ = State::action;
    return;
  }
  actions_.begin(path_, now_s);
  if (actions_.pending()) {
    state_ = State::action;
    return;
  }
  actions_done(now_s);
}

void Controller::actions_done(double now_s) {
  // Only the new entries: the report's log is reserved as the runner's, so this never allocates.
  const std::vector<ActionEvent>& log = actions_.log();
  report_.actions.insert(report_.actions.end(), log.begin() + static_cast<std::ptrdiff_t>(report_.actions.size()), log.end());
  report_.action_counts = actions_.counts();
  if (path_ < job_.path_count()) begin_travel(pierce_at_);
  else finish_job(now_s);
}

double Controller::pierce_delay() const {
  const double d = path_ < job_.path_count() ? head_->pierce_delay_s : -1.0;
  return d >= 0.0 ? d : cfg_.pierce_delay_s;
}

void Controller::finish_job(double now_s) {
  // The program's outputs end off, as the torch does.
  if (cfg_.outputs != nullptr && !cfg_.outputs->all_off()) {
    stop(State::fault, cfg_.outputs->last_error(), now_s);
    return;
  }
  state_ = State::done;
  report_.state = State::done;
  if (journal_ && !journal_finished()) {
    journal_failed_ = true;
    stop(State::fault, journal_error(), now_s);
    return;
  }
  report_.stopped_at = st_.position;
  finished_ = true;
}

}  // namespace kerf::control
