// `kerf sim`: fit a job, start the simulated motion board, stream the
// segments to it over Modbus (TCP on 127.0.0.1 or RTU on a pty) and report
// what it executed.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "cli/sim_options.hpp"
#include "kerf/sim/segment_executor.hpp"

namespace kerf::cli {

// Makes the board's executor, or returns null with the reason in why_not.
using ExecutorFactory = std::function<std::unique_ptr<sim::SegmentExecutor>(std::string& why_not)>;

// Runs it with the board's motion executor; returns the exit code.
int run_sim(const SimOptions& opts);
// The same with another executor (tests of the streaming path).
int run_sim_with(const SimOptions& opts, const ExecutorFactory& make_executor);

}  // namespace kerf::cli
