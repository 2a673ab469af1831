// Declarative controller scenarios (tests/scenarios/*.toml): a job, a config,
// scripted GPIO and board events, and the expected outcome. The format:
//
//   description = "..."
//   job = "jobs/square_and_circle.txt"   # relative to the scenario file
//   config = "sim.toml"                  # optional; default firmware/examples/sim.toml
//   tol = 0.05                           # optional fit tolerance (mm)
//   gpio = """                           # optional GPIO script (sim/README.md)
//   4.3 estop on
//   """
//   faults = ["drive-fault@2.0"]         # optional board-side faults, as `kerf sim --fault`
//
//   [expect]
//   state = "estop"                      # done | fault | estop
//   reason = "E-stop"                    # a substring of the stop reason
//   torch = "on off on off"              # the torch output's changes, in order
//   paths_completed = 1                  # paths cut to their end
//   pierces = 2
//   safe_stop_at = 4.3                   # torch off within one cycle of this time, axes
//                                        # stopped within the braking distance of it
//   torch_off_by = 0.6                   # or: torch off within this long after safe_stop_at
//   resume = true                        # resume from the journal: the rest is cut once
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace kerf::test {

struct Scenario {
  std::string file, description;
  std::string job, config;
  std::optional<double> tol;
  std::string gpio_script;
  std::vector<std::string> faults;
  struct Expect {
    std::string state, reason, torch;
    std::optional<long> paths_completed, pierces;
    std::optional<double> safe_stop_at, torch_off_by;
    bool resume = false;
  } expect;
};

// Reads a scenario; false with `error` ("FILE:LINE: reason").
bool load_scenario(const std::string& path, const std::string& examples_dir, Scenario& out, std::string& error);

}  // namespace kerf::test
