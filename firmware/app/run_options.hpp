// `kerf run`'s options, as given (checked by run_command.cpp).
#pragma once

#include <string>

namespace CLI {
class App;
class Option;
}

namespace kerf::app {

struct RunOptions {
  std::string config;   // required
  std::string journal;
  bool resume = false;
  bool reset = false;     // the E-stop latch's reset edge at start-up
  bool dry_run = false;   // torch and gas outputs held off
  bool assume_homed = false;  // a machine without home switches: the operator confirms the position
  std::string report;
  std::string job;      // point file (paths separated by blank lines)
};

CLI::App* add_run_command(CLI::App& app, RunOptions& opts);

// The options `kerf run` and `kerf-sim sim` share, with the same help.
void add_journal_options(CLI::App* command, std::string& journal, bool& resume);
void add_report_option(CLI::App* command, std::string& report);
void add_dry_run_option(CLI::App* command, bool& dry_run);
// The job, positional `name`; the caller gives its type name.
CLI::Option* add_job_file(CLI::App* command, const std::string& name, std::string& file);

}  // namespace kerf::app
