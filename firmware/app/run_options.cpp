// `kerf run`'s options. Built in every configuration, so that --help is the
// same everywhere; running it needs the Modbus link (run_command.cpp).
#include <CLI/CLI.hpp>

#include "app/run_options.hpp"

namespace kerf::cli {

CLI::App* add_run_command(CLI::App& app, RunOptions& o) {
  CLI::App* r = app.add_subcommand(
      "run", "Cut a job on the machine: the motion board over Modbus, the torch and safety inputs on GPIO");
  r->add_option("--config", o.config, "Machine configuration (TOML)")->type_name("FILE")->required();
  r->add_option("--journal", o.journal, "Progress journal: every completed segment, synced")->type_name("FILE");
  r->add_flag("--resume", o.resume, "Finish the job the journal belongs to, from where it stopped");
  r->add_flag("--sim-gpio", o.sim_gpio,
              "Bench mode: simulate the torch and inputs (arc-OK follows the torch). Never on a machine with a torch");
  r->add_option("--report", o.report, "Write the JSON report here")->type_name("R.json");
  r->add_option("job", o.job, "Point file (paths separated by blank lines); - for stdin")
      ->type_name("JOB")
      ->required();
  return r;
}

}  // namespace kerf::cli
