// `kerf sim`'s trace, taken as the run makes it (SimMachineConfig::trace_sink)
// in memory that does not grow with simulated time: the CSV is written as it
// goes, the path deviation is a running maximum, and the plot keeps at most
// `plot_budget` samples (every sample while the run is short; then every
// 2nd, 4th ... sample, and always the two at each torch change, so the SVG's
// cut and rapid runs and pierce marks are those of the whole trace).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "io/run_svg.hpp"
#include "kerf/fit/fit.hpp"
#include "kerf/sim/motion_board.hpp"

namespace kerf::simulated {

class TraceRecorder {
 public:
  TraceRecorder(const std::vector<fit::Piece<double>>& pieces, bool with_z, bool plot, std::size_t plot_budget);
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

  const std::vector<fit::Piece<double>>& pieces_;
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
