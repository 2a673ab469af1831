// What `kerf sim` writes: the executed trace (CSV), the JSON report and the
// one-line summary, from a finished run of the simulated machine.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "simulated/sim_machine.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::io {

struct SimSummary {
  bool simulated = true;  // kerf sim; false for kerf run (no trace, no simulated time)
  std::string state;   // done | fault | estop
  std::string reason;  // empty when done
  std::string link;    // modbus-tcp | modbus-rtu
  std::size_t paths = 0, pierces = 0;
  std::size_t planned = 0;          // segments in the job
  std::size_t executed = 0;         // completed in this run
  std::uint64_t executed_total = 0; // completed over every run of the job (the journal's count)
  std::uint64_t duplicates = 0;     // segments completed more than once
  std::int64_t last_executed = 0;   // 1-based number of the last completed segment, 0 for none
  std::size_t resumed_from = 0;     // 1-based first segment of this run; 0: a new job
  std::uint32_t runs = 1;
  bool has_cut_to = false;          // where the torch went off inside the next segment
  control::CutPoint cut_to;
  bool torch_on = false;
  bool torch_off_valid = false;
  Vec2<double> torch_off_at{}, stopped_at{};
  std::uint64_t link_errors = 0;
  std::uint32_t board_duplicates = 0;  // resent segments the board dropped
  double max_path_deviation_mm = 0.0;
  double duration_s = 0.0;  // simulated
  double wall_s = 0.0;
  std::string rt;           // the cycle loop's statistics, when paced in real time
  std::string rt_histogram; // its wake-up lateness histogram, one bin per line
};

// The summary's fields that come from the controller's report and the
// journal (when there is one; otherwise from this run alone). `resumed`:
// this run started from a journal.
SimSummary summarise_run(const control::RunReport& r, std::size_t paths, const std::string& link, bool resumed,
                         const control::Journal* journal);

// Largest distance of an executed sample (running job segment k + 1) from
// fitted piece k or a piece next to it.
double max_path_deviation(const std::vector<sim::TraceSample>& trace,
                          const std::vector<fit::Piece<double>>& pieces);

std::string format_trace_csv(const std::vector<sim::TraceSample>& trace);
std::string format_sim_json(const SimSummary& s);
std::string format_sim_summary(const SimSummary& s);

}  // namespace kerf::io
