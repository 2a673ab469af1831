// `kerf run`: the controller on the real machine. The job is fitted path by
// path, the configuration's safety rules are checked before any device is
// opened (machine/machine_factory.hpp), the link (Modbus or CAN) and the
// lines (libgpiod) are made by the machine factory, and the controller runs
// in a periodic loop on absolute deadlines (SCHED_FIFO and mlockall where
// permitted). SIGINT or SIGTERM stop it safely: torch off, motion stopped
// on the path, progress kept in the journal.
#pragma once

#include <memory>
#include <string>

#include "app/run_options.hpp"
#include "config/config.hpp"
#include "kerf/hal/gpio.hpp"

namespace kerf::app {

// Returns the exit code: 0 done, 1 stopped (fault, E-stop, signal), refused
// by the safety rules, or a device failed, 2 bad options, config or job.
int run_run(const RunOptions& opts);

// The run as kerf and kerf-sim share it: `check` is the configuration's rules
// (refused before the job is even read), `open_lines` gives the lines.
// `who` prefixes messages ("kerf", "kerf-sim").
using RunCheck = bool (*)(const config::Config& cfg, std::string& error);
using LinesOpener = std::unique_ptr<hal::Gpio> (*)(const config::Config& cfg, std::string& error);
int run_job(const RunOptions& opts, const char* who, RunCheck check, LinesOpener open_lines);

}  // namespace kerf::app
