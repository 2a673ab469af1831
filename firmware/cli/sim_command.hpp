// `kerf sim`: fit a job, start the simulated motion board, stream the
// segments to it over Modbus (TCP on 127.0.0.1 or RTU on a pty) and report
// what it executed.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "kerf/sim/segment_executor.hpp"

namespace CLI {
class App;
}

namespace kerf::cli {

struct SimOptions {
  std::string link;                 // modbus-tcp | modbus-rtu
  std::string tol;
  std::string criterion = "vertex";
  std::string feed = "50";          // mm/s
  std::vector<std::string> faults;  // KIND@SECONDS[:DURATION]
  std::string report;
  std::string trace;
  std::string speed = "0";          // 0: as fast as possible
  std::string link_timeout = "1";   // s
  std::string file;
};

CLI::App* add_sim_command(CLI::App& app, SimOptions& opts);

// Makes the board's executor, or returns null with the reason in why_not.
using ExecutorFactory = std::function<std::unique_ptr<sim::SegmentExecutor>(std::string& why_not)>;

// Runs it with the board's motion executor; returns the exit code.
int run_sim(const SimOptions& opts);
// The same with another executor (tests of the streaming path).
int run_sim_with(const SimOptions& opts, const ExecutorFactory& make_executor);

}  // namespace kerf::cli
