// `kerf sim`'s options. Built in every configuration, so that --help is the
// same everywhere; running it needs libmodbus (sim_command.cpp).
#include <CLI/CLI.hpp>

#include "app/run_options.hpp"
#include "app/sim_options.hpp"

namespace kerf::app {

CLI::App* add_sim_command(CLI::App& app, simulated::SimOptions& o) {
  CLI::App* s = app.add_subcommand(
      "sim",
      "Run a job on the simulated machine (motion board over Modbus, torch and inputs on simulated GPIO). "
      "With no arguments: the built-in demo job, writing kerf-sim.csv, kerf-sim.svg and kerf-sim.json");
  s->add_option("--config", o.config, "Machine configuration (TOML); default: built-in defaults")
      ->type_name("FILE");
  s->add_option("--link", o.link, "modbus-tcp, modbus-rtu or can (default: the config's)")->type_name("LINK");
  s->add_option("--axes", o.axes, "can: drives on the bus, 2 or 3 (default: the config's axes)")->type_name("N");
  s->add_option("--sync-ms", o.sync_ms, "can: SYNC period in ms, 1..10 (default: the config's)")->type_name("P");
  s->add_option("--iface", o.iface, "can: a SocketCAN interface such as vcan0 (default: the in-process bus)")
      ->type_name("IFACE");
  s->add_option("--tol", o.tol, "Fit tolerance in mm (default: the config's)")->type_name("EPS");
  s->add_option("--criterion", o.criterion, "vertex or band (default: the config's)")->type_name("NAME");
  s->add_option("--numeric", o.numeric,
                "Scalar type of the fit: double or fixed (Q31.32; vertex and band) (default: the config's)")
      ->type_name("TYPE");
  s->add_option("--feed", o.feed, "Cut feed in mm/min (default: the config's)")->type_name("MM_PER_MIN");
  s->add_option("--fault", o.faults,
                "KIND@SECONDS[:DURATION]: estop, arc-lost, no-arc, limit, hold, cycle-start, reset, drive-fault, "
                "stall (the x axis jams); "
                "modbus: link-drop, link-stall, modbus-exception, crc-error; can: heartbeat-loss, emcy, bus-off, "
                "enable-refused")
      ->type_name("FAULT");
  s->add_option("--gpio-script", o.gpio_script, "Timed GPIO events (see sim/README.md)")->type_name("FILE");
  add_journal_options(s, o.journal, o.resume);
  add_report_option(s, o.report);
  add_dry_run_option(s, o.dry_run);
  s->add_option("--trace", o.trace, "Write the executed trace (CSV) here")->type_name("T.csv");
  s->add_option("--plot", o.plot, "Write an SVG plot of the run here")->type_name("P.svg");
  s->add_option("--speed", o.speed, "Simulated s per wall s; 0 = as fast as possible")
      ->type_name("X")
      ->capture_default_str();
  s->add_option("--link-timeout", o.link_timeout, "Give up when the link is down this long (s)")
      ->type_name("S");
  add_job_file(s, "file", o.file)->type_name("FILE|-");
  return s;
}

}  // namespace kerf::app
