// kerf-drive-sim: simulated CiA 402 drives on a SocketCAN interface, so the
// controller and the drives run as separate processes (the HIL bench on
// vcan0). Runs until SIGTERM/SIGINT, or until --idle-exit-ms pass without a
// frame once SYNC has started.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "kerf/sim/can/socket_drives.hpp"

namespace {
std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Simulated CiA 402 drives on a SocketCAN interface"};
  std::string iface = "vcan0";
  std::vector<int> nodes{1, 2};
  std::string log_path;
  std::string fault = "none";
  int fault_node = 1;
  long fault_after_syncs = 0;
  long idle_exit_ms = 0;
  double lag = 1.0;
  app.add_option("--iface", iface, "SocketCAN interface");
  app.add_option("--nodes", nodes, "node ids, one drive each")->delimiter(',')->check(CLI::Range(1, 127));
  app.add_option("--log", log_path, "candump -L log of every frame seen or sent");
  app.add_option("--fault", fault, "fault to inject")
      ->check(CLI::IsMember({"none", "heartbeat-loss", "emcy", "enable-refused"}));
  app.add_option("--fault-node", fault_node, "node that faults")->check(CLI::Range(1, 127));
  app.add_option("--fault-after-syncs", fault_after_syncs, "SYNCs seen before the fault")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--idle-exit-ms", idle_exit_ms, "exit after this long without a frame, once SYNC ran (0: never)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--lag", lag, "plant: fraction of the error closed per SYNC")->check(CLI::Range(0.01, 1.0));
  std::vector<long> switches;
  app.add_option("--home-switch", switches,
                 "home switch of each drive in --nodes order (x, y, then z: the third node), counts (homing mode 6, methods 17/18)")
      ->delimiter(',');
  CLI11_PARSE(app, argc, argv);

  std::vector<kerf::sim::DriveConfig> configs;
  for (int n : nodes) {
    kerf::sim::DriveConfig c;
    c.node = static_cast<std::uint8_t>(n);
    c.lag_alpha = lag;
    if (configs.size() < switches.size()) {
      c.has_home_switch = true;
      c.home_switch = static_cast<std::int32_t>(switches[configs.size()]);
    }
    configs.push_back(c);
  }
  std::string error;
  auto drives = kerf::sim::SocketDrives::open(iface, configs, log_path, error);
  if (!drives) {
    std::fprintf(stderr, "kerf-drive-sim: %s\n", error.c_str());
    return 1;
  }
  if (fault != "none") {
    const auto kind = fault == "heartbeat-loss" ? kerf::sim::DriveFault::heartbeat_loss
                      : fault == "emcy"          ? kerf::sim::DriveFault::emcy
                                                 : kerf::sim::DriveFault::enable_refused;
    drives->inject(static_cast<std::uint8_t>(fault_node), kind, static_cast<std::uint64_t>(fault_after_syncs));
  }
  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);
  if (!drives->serve(g_stop, static_cast<std::uint64_t>(idle_exit_ms) * 1000u, error)) {
    std::fprintf(stderr, "kerf-drive-sim: %s\n", error.c_str());
    return 1;
  }
  std::fprintf(stderr, "kerf-drive-sim: %llu SYNCs seen\n", static_cast<unsigned long long>(drives->syncs()));
  return 0;
}
