// `kerf sim`'s options. Built in every configuration, so that --help is the
// same everywhere; running it needs libmodbus (sim_command.cpp).
#include <CLI/CLI.hpp>

#include "cli/sim_options.hpp"

namespace kerf::cli {

CLI::App* add_sim_command(CLI::App& app, SimOptions& o) {
  CLI::App* s = app.add_subcommand(
      "sim", "Fit, then cut on the simulated motion board over Modbus");
  s->add_option("--link", o.link, "modbus-tcp or modbus-rtu")->type_name("LINK")->required();
  s->add_option("--tol", o.tol, "Fit tolerance (> 0)")->type_name("EPS")->required();
  s->add_option("--criterion", o.criterion, "Fit criterion (only: vertex)")
      ->type_name("NAME")
      ->capture_default_str();
  s->add_option("--feed", o.feed, "Feed in mm/min")->type_name("MM_PER_MIN")->capture_default_str();
  s->add_option("--fault", o.faults,
                "KIND@SECONDS[:DURATION]: link-drop, link-stall, modbus-exception, crc-error")
      ->type_name("FAULT");
  s->add_option("--report", o.report, "Write the JSON report here")->type_name("R.json");
  s->add_option("--trace", o.trace, "Write the executed trace (CSV) here")->type_name("T.csv");
  s->add_option("--speed", o.speed, "Simulated s per wall s; 0 = as fast as possible")
      ->type_name("X")
      ->capture_default_str();
  s->add_option("--link-timeout", o.link_timeout, "Give up when the link is down this long (s)")
      ->type_name("S")
      ->capture_default_str();
  s->add_option("file", o.file, "Point file; - for stdin")->type_name("FILE|-")->required();
  return s;
}

}  // namespace kerf::cli
