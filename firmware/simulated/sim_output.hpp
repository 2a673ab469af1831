// What only `kerf sim` writes: the executed trace (CSV), and how far it
// strayed from the fitted path. The report both sim and run write is
// control/run_report.hpp's.
#pragma once

#include <string>
#include <vector>

#include "kerf/fit/fit.hpp"
#include "simulated/sim_machine.hpp"

namespace kerf::simulated {

// Largest distance of an executed sample (running job segment k + 1) from
// fitted piece k or a piece next to it.
double max_path_deviation(const std::vector<sim::TraceSample>& trace,
                          const std::vector<fit::Piece<double>>& pieces);

// One line a sample; with_z (a machine with a z axis) adds a last column z_mm.
std::string format_trace_csv(const std::vector<sim::TraceSample>& trace, bool with_z = false);

}  // namespace kerf::simulated
