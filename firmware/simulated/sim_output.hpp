// What only `kerf sim` writes: the executed trace (CSV), and how far it
// strayed from the fitted path, one sample at a time (trace_recorder.hpp
// takes them as the run goes). The report both sim and run write is
// control/run_report.hpp's.
#pragma once

#include <cstddef>
#include <vector>

#include "kerf/fit/fit.hpp"
#include "kerf/sim/motion_board.hpp"

namespace kerf::simulated {

// Distance of an executed sample (running job segment k + 1, k < pieces.size())
// from fitted piece k or a piece next to it.
double sample_deviation(const sim::TraceSample& s, const std::vector<fit::Piece<double>>& pieces);

// The CSV's first line; with_z (a machine with a z axis) adds a last column z_mm.
const char* csv_header(bool with_z);
// One CSV line (with its '\n') into `out`; returns its length.
int format_trace_row(const sim::TraceSample& s, bool with_z, char* out, std::size_t size);

}  // namespace kerf::simulated
