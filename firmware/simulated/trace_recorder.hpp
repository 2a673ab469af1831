// `kerf sim`'s trace, taken as the run makes it (SimMachineConfig::trace_sink)
// in memory that does not grow with simulated time nor with the job: the CSV
// is written as it goes, the path deviation is a running maximum against the
// pieces of the segment being run and its neighbours (looked up when the
// segment changes: a streamed job keeps only recent ones), and the plot keeps at most
// `plot_budget` samples (every sample while the run is short; then every
// 2nd, 4th ... sample, and always the two at each torch change, so the SVG's
// cut and rapid runs and pierce marks are those of the whole trace).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "io/run_svg.hpp"
#include "kerf/geom/segment.hpp"
#include "kerf/sim/motion_board.hpp"

namespace kerf::simulated {

class TraceRecorder {
 public:
  // Job segment k's fitted piece into `out`; false if it is not known (any more).
  using PieceLookup = std::function<bool(std::size_t k, Segment<double>& out)>;
  TraceRecorder(PieceLookup pieces, bool with_z, bool plot, std::size_t plot_budget);
  ~TraceRecorder();
  TraceRecorder(const TraceRecorder&) = delete;
  TraceRecorder& operator=(const TraceRecorder&) = delete;

  // Writes the CSV to `path` as samples come ("-": stdout; a regular file
  // through PATH.tmp, renamed by finish_csv). False with errno set.
  bool open_csv(const std::string& path);
  void take(const sim::TraceSample& s);
  // Flushes and renames the CSV into place; false with errno set (and no
  // file left) on a write error. True when no CSV was opened.
  bool finish_csv();

  double max_deviation() const { return max_dev_; }
  std::uint64_t samples() const { return n_; }
  std::vector<io::TraceSample> plot_trace() const;

 private:
  struct Kept {
    io::TraceSample s;
    std::uint64_t index;  // the sample's number in the whole trace
    bool torch_change;    // kept whatever the stride
  };
  void thin();
  void look_up(std::size_t k);

  PieceLookup pieces_;
  // Pieces k - 1, k, k + 1 of the segment k being run (have_: known).
  std::size_t near_k_ = SIZE_MAX;
  Segment<double> near_[3]{};
  bool have_[3] = {false, false, false};
  bool with_z_, plot_;
  std::size_t budget_, limit_;
  std::uint64_t n_ = 0, stride_ = 1;
  double max_dev_ = 0.0;
  std::vector<Kept> kept_;
  bool last_torch_ = false;
  io::TraceSample last_{};
  std::FILE* csv_ = nullptr;
  bool csv_ok_ = true;
  int csv_errno_ = 0;
  std::string csv_path_, csv_tmp_;
};

}  // namespace kerf::simulated
