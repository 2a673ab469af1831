#include "simulated/trace_recorder.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <utility>

#include "simulated/sim_output.hpp"

namespace kerf::simulated {

TraceRecorder::TraceRecorder(PieceLookup pieces, bool with_z, bool plot, std::size_t plot_budget)
    : pieces_(std::move(pieces)), with_z_(with_z), plot_(plot), budget_(std::max<std::size_t>(plot_budget, 16)),
      limit_(budget_) {
  if (plot_) kept_.reserve(budget_);
}

TraceRecorder::~TraceRecorder() {
  if (csv_ != nullptr && csv_ != stdout) {
    std::fclose(csv_);
    if (!csv_tmp_.empty()) std::remove(csv_tmp_.c_str());  // never finished: no half file
  }
}

bool TraceRecorder::open_csv(const std::string& path) {
  csv_path_ = path;
  if (path == "-") {
    csv_ = stdout;
  } else {
    struct stat st {};
    // A device or fifo is written in place; a regular file through PATH.tmp.
    const bool special = ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
    if (!special) csv_tmp_ = path + ".tmp";
    csv_ = std::fopen(special ? path.c_str() : csv_tmp_.c_str(), "wb");
    if (csv_ == nullptr) return false;
  }
  std::fputs(csv_header(with_z_), csv_);
  return true;
}

void TraceRecorder::look_up(std::size_t k) {
  if (k != near_k_) {
    near_k_ = k;
    have_[0] = k > 0 && pieces_(k - 1, near_[0]);
    have_[1] = pieces_(k, near_[1]);
    have_[2] = false;
  }
  // The next piece may not have been read yet when k starts running.
  if (!have_[2]) have_[2] = pieces_(k + 1, near_[2]);
}

void TraceRecorder::take(const sim::TraceSample& s) {
  if (s.seq != 0 && pieces_) {
    look_up(s.seq - 1);
    if (have_[1]) {
      const Segment<double>* const near[3] = {have_[0] ? &near_[0] : nullptr, &near_[1], have_[2] ? &near_[2] : nullptr};
      max_dev_ = std::max(max_dev_, sample_deviation(s.pos, near));
    }
  }
  if (csv_ != nullptr && csv_ok_) {
    char line[192];
    const int len = format_trace_row(s, with_z_, line, sizeof line);
    if (std::fwrite(line, 1, static_cast<std::size_t>(len), csv_) != static_cast<std::size_t>(len)) {
      csv_ok_ = false;
      csv_errno_ = errno;
    }
  }
  if (plot_) {
    const io::TraceSample p{s.t_s, s.pos, s.seq, s.torch};
    const bool change = n_ > 0 && s.torch != last_torch_;
    if (change && (n_ - 1) % stride_ != 0 && (kept_.empty() || kept_.back().index != n_ - 1))
      kept_.push_back({last_, n_ - 1, true});  // the sample before the change
    if (change || n_ % stride_ == 0) kept_.push_back({p, n_, change});
    if (kept_.size() >= limit_) thin();
    last_ = p;
  }
  last_torch_ = s.torch;
  ++n_;
}

void TraceRecorder::thin() {
  // Twice the stride; the torch changes and the samples before them stay.
  stride_ *= 2;
  std::size_t w = 0;
  for (std::size_t r = 0; r < kept_.size(); ++r) {
    const bool before_change = r + 1 < kept_.size() && kept_[r + 1].torch_change && kept_[r + 1].index == kept_[r].index + 1;
    if (kept_[r].index % stride_ == 0 || kept_[r].torch_change || before_change) kept_[w++] = kept_[r];
  }
  kept_.resize(w);
  // Torch changes alone can fill the budget (they grow with the job, not time).
  limit_ = std::max(budget_, 2 * w);
}

bool TraceRecorder::finish_csv() {
  if (csv_ == nullptr) return true;
  bool ok = csv_ok_ && std::fflush(csv_) == 0 && std::ferror(csv_) == 0;
  int why = ok ? 0 : (csv_errno_ != 0 ? csv_errno_ : errno);
  if (csv_ != stdout && std::fclose(csv_) != 0 && ok) {
    ok = false;
    why = errno;
  }
  csv_ = nullptr;
  if (ok && !csv_tmp_.empty() && std::rename(csv_tmp_.c_str(), csv_path_.c_str()) != 0) {
    ok = false;
    why = errno;
  }
  if (!ok) {
    if (!csv_tmp_.empty()) std::remove(csv_tmp_.c_str());
    errno = why;
  }
  csv_tmp_.clear();
  return ok;
}

std::vector<io::TraceSample> TraceRecorder::plot_trace() const {
  std::vector<io::TraceSample> out;
  out.reserve(kept_.size() + 1);
  for (const Kept& k : kept_) out.push_back(k.s);
  // The last sample, so the drawing ends where the axes stopped.
  if (n_ > 0 && (kept_.empty() || kept_.back().index != n_ - 1)) out.push_back(last_);
  return out;
}

}  // namespace kerf::simulated
