// `kerf run`'s options (kerf-sim's bench run takes the same).
#include <CLI/CLI.hpp>

#include "app/run_options.hpp"

namespace kerf::app {

CLI::App* add_run_command(CLI::App& app, RunOptions& o) {
  CLI::App* r = app.add_subcommand(
      "run",
      "Cut a job on the machine: the motion board over Modbus or the drives over CAN, the torch and safety inputs on "
      "GPIO (a bench without a torch: [bench] enabled = true in the configuration)");
  r->add_option("--config", o.config, "Machine configuration (TOML)")->type_name("FILE")->required();
  add_journal_options(r, o.journal, o.resume);
  r->add_flag("--reset", o.reset,
              "Reset the E-stop latch at start-up (refused while the E-stop is asserted); without it the "
              "configured gpio.reset line must be pressed");
  r->add_flag("--assume-homed", o.assume_homed,
              "The machine has no home switches ([machine] home_switches = false): the operator confirms the "
              "position at start-up; written into the report. Otherwise `kerf home` must have homed every axis");
  add_report_option(r, o.report);
  add_dry_run_option(r, o.dry_run);
  add_job_file(r, "job", o.job)->type_name("JOB")->required();
  return r;
}

void add_journal_options(CLI::App* command, std::string& journal, bool& resume) {
  command->add_option("--journal", journal, "Progress journal: every completed segment, synced")->type_name("FILE");
  command->add_flag("--resume", resume, "Finish the job the journal belongs to, from where it stopped");
}

void add_dry_run_option(CLI::App* command, bool& dry_run) {
  command->add_flag("--dry-run", dry_run,
                    "Run the job with the torch and gas outputs held off: no pierce, no arc-OK wait (the summary "
                    "and the report say dry run)");
}

void add_report_option(CLI::App* command, std::string& report) {
  command->add_option("--report", report, "Write the JSON report here")->type_name("R.json");
}

CLI::Option* add_job_file(CLI::App* command, const std::string& name, std::string& file) {
  return command->add_option(name, file, "Point file (paths separated by blank lines); - for stdin");
}

}  // namespace kerf::app
