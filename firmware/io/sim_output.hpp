// What `kerf sim` writes: the executed trace (CSV), the JSON report and the
// human summary, from a finished simulated job and the fitted path.
#pragma once

#include <string>
#include <vector>

#include "control/sim_job.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::io {

struct SimSummary {
  std::string state;  // done | fault | estop
  std::string fault;  // empty: none
  std::string link;   // modbus-tcp | modbus-rtu
  std::uint32_t planned = 0, sent = 0, executed = 0, last_executed = 0;
  std::uint64_t resent = 0;
  std::uint32_t duplicates = 0;
  bool torch_on = false;
  double max_path_deviation_mm = 0.0;
  double duration_s = 0.0;  // simulated
  double wall_s = 0.0;
};

// Largest distance of an executed sample (one running segment k) from fitted piece k.
double max_path_deviation(const std::vector<sim::TraceSample>& trace,
                          const std::vector<fit::Piece<double>>& pieces);

SimSummary summarise(const control::SimJobResult& r, const std::vector<fit::Piece<double>>& pieces,
                     const std::string& link);

std::string format_trace_csv(const std::vector<sim::TraceSample>& trace);
std::string format_sim_json(const SimSummary& s);
std::string format_sim_summary(const SimSummary& s);

}  // namespace kerf::io
