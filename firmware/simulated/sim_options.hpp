// `kerf sim`'s options, as given (still text: run_sim checks them so every
// message has the "kerf: --option: ..." form). An empty value means "not
// given": the config's value (or its default) applies.
#pragma once

#include <string>
#include <vector>

namespace kerf::simulated {

struct SimOptions {
  std::string config;               // TOML; empty: the built-in defaults
  std::string link;                 // modbus-tcp | modbus-rtu
  std::string tol;
  std::string criterion;
  std::string numeric;  // the fit's scalar type; empty: the config's (fit.numeric)
  std::string feed;                 // mm/min
  std::vector<std::string> faults;  // KIND@SECONDS[:DURATION]
  std::string gpio_script;          // timed GPIO events (sim/README.md)
  std::string journal;
  bool resume = false;
  bool dry_run = false;             // torch and gas outputs held off
  std::string report;
  std::string trace;
  std::string plot;
  std::string speed = "0";          // 0: as fast as possible
  std::string link_timeout;         // s
  std::string axes;                 // can: 2 or 3 (default: the config's axes)
  std::string sync_ms;              // can: SYNC period, 1..10 ms (default: the config's)
  std::string iface;                // can: a SocketCAN interface (vcan0); empty: the in-process bus
  std::string file;                 // empty: the built-in demo job
  // Tests only (no option): the file read and fitted whole before the run,
  // the oracle a streamed run is compared against.
  bool whole_job = false;
};

}  // namespace kerf::simulated
