// Where the controller reads its job (control/job_source.hpp) and which job
// segment each wire segment carries.
#include "control/controller.hpp"

namespace kerf::control {

// job_of_wire_: the job segment k of each wire segment; -1 a rapid; -2 - k
// the first part of k's rest split in two on resume (it does not complete k).
std::int64_t Controller::job_segment_of(std::uint32_t seq) const {
  if (!wire_known(seq)) return -1;
  const std::int64_t v = job_of_wire_[seq % kWireWindow];
  return v < -1 ? -v - 2 : v;
}

bool Controller::completes_job_segment(std::uint32_t seq) const {
  return wire_known(seq) && job_of_wire_[seq % kWireWindow] >= 0;
}

std::int64_t Controller::wire_job(std::size_t i) const {
  const auto k = static_cast<std::int64_t>(next_seg_ + (i > queue_extra_ ? i - queue_extra_ : 0));
  return i < queue_extra_ ? -k - 2 : k;
}

const hal::SegmentCommand* Controller::next_wire() {
  if (sent_ < queue_.size()) return &queue_[sent_];
  if (block_ != Block::cut || path_ended_ || pulled_ != nullptr) return pulled_;
  const hal::SegmentCommand* c = nullptr;
  const Pull p = job_.segment(path_next_, c);
  path_ended_ = p == Pull::end;
  if (p == Pull::ready) pulled_ = c;  // until it is sent
  if (p == Pull::error && stop_request_.empty()) stop_request_ = std::string("job: ") + job_.error();  // a fault next cycle
  return pulled_;
}

}  // namespace kerf::control
