// `kerf sim`'s options, as given (still text: run_sim checks them so every
// message has the "kerf: --option: ..." form).
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace kerf::cli {

struct SimOptions {
  std::string link;                 // modbus-tcp | modbus-rtu
  std::string tol;
  std::string criterion = "vertex";
  std::string feed = "3000";        // mm/min
  std::vector<std::string> faults;  // KIND@SECONDS[:DURATION]
  std::string report;
  std::string trace;
  std::string speed = "0";          // 0: as fast as possible
  std::string link_timeout = "1";   // s
  std::string file;
};

CLI::App* add_sim_command(CLI::App& app, SimOptions& opts);

}  // namespace kerf::cli
