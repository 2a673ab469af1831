// What only `kerf sim` writes: the executed trace (CSV), and how far it
// strayed from the fitted path, one sample at a time (trace_recorder.hpp
// takes them as the run goes). The report both sim and run write is
// control/run_report.hpp's.
#pragma once

#include <cstddef>

#include "kerf/geom/segment.hpp"
#include "kerf/sim/motion_board.hpp"

namespace kerf::simulated {

// Distance of an executed sample (running job segment k + 1) from fitted
// piece k or a piece next to it: near[0..2] are pieces k - 1, k and k + 1,
// null where there is none (or it is not known).
double sample_deviation(Vec2<double> pos, const Segment<double>* const near[3]);

// The CSV's first line; with_z (a machine with a z axis) adds a last column z_mm.
const char* csv_header(bool with_z);
// One CSV line (with its '\n') into `out`; returns its length.
int format_trace_row(const sim::TraceSample& s, bool with_z, char* out, std::size_t size);

}  // namespace kerf::simulated
