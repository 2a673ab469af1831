// kerf-drive-sim: simulated CiA 402 drives on a SocketCAN interface, so the
// controller and the drives run as separate processes (the HIL bench on
// vcan0). Runs until SIGTERM/SIGINT, or until --idle-exit-ms pass without a
// frame once SYNC has started. Optionally logs every frame it sees or sends
// in candump -L format.
#include <csignal>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "kerf/hal/can/socket_can_bus.hpp"
#include "kerf/sim/can/drive_node.hpp"
#include "kerf/sim/can/virtual_can_bus.hpp"

namespace {

volatile std::sig_atomic_t g_stop = 0;
void on_signal(int) { g_stop = 1; }

// Sends through the socket and logs what went out.
class LoggingBus final : public kerf::hal::CanBus {
 public:
  LoggingBus(kerf::hal::CanBus& inner, std::ofstream* log, std::string iface)
      : inner_(inner), log_(log), iface_(std::move(iface)) {}
  kerf::hal::CanResult send(const kerf::hal::CanFrame& f) override {
    const auto r = inner_.send(f);
    if (r == kerf::hal::CanResult::ok) record(f);
    return r;
  }
  kerf::hal::CanResult receive(kerf::hal::CanFrame& f, std::uint64_t until_us) override {
    const auto r = inner_.receive(f, until_us);
    if (r == kerf::hal::CanResult::ok) record(f);
    return r;
  }
  std::uint64_t now_us() override { return inner_.now_us(); }
  kerf::hal::BusState state() const override { return inner_.state(); }
  bool recovered() override { return inner_.recovered(); }
  const kerf::hal::CanCounters& counters() const override { return inner_.counters(); }
  const char* last_error() const override { return inner_.last_error(); }

 private:
  void record(const kerf::hal::CanFrame& f) {
    if (log_ != nullptr) *log_ << kerf::sim::candump_line(inner_.now_us(), iface_, f) << '\n';
  }
  kerf::hal::CanBus& inner_;
  std::ofstream* log_;
  std::string iface_;
};

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
  app.add_option("--fault-after-syncs", fault_after_syncs, "SYNCs seen before the fault")->check(CLI::NonNegativeNumber);
  app.add_option("--idle-exit-ms", idle_exit_ms, "exit after this long without a frame, once SYNC ran (0: never)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--lag", lag, "plant: fraction of the error closed per SYNC")->check(CLI::Range(0.01, 1.0));
  CLI11_PARSE(app, argc, argv);

  std::string error;
  auto sock = kerf::hal::SocketCanBus::open(iface, {}, error);
  if (!sock) {
    std::fprintf(stderr, "kerf-drive-sim: %s\n", error.c_str());
    return 1;
  }
  std::unique_ptr<std::ofstream> log;
  if (!log_path.empty()) {
    log = std::make_unique<std::ofstream>(log_path);
    if (!*log) {
      std::fprintf(stderr, "kerf-drive-sim: %s: cannot write the log\n", log_path.c_str());
      return 1;
    }
  }
  LoggingBus bus(*sock, log.get(), iface);
  std::vector<std::unique_ptr<kerf::sim::DriveNode>> drives;
  for (int n : nodes) {
    kerf::sim::DriveConfig c;
    c.node = static_cast<std::uint8_t>(n);
    c.lag_alpha = lag;
    drives.push_back(std::make_unique<kerf::sim::DriveNode>(c, bus));
  }
  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);
  for (auto& d : drives) d->power_on(bus.now_us());
  long syncs = 0;
  bool injected = fault == "none";
  std::uint64_t last_frame_us = bus.now_us();
  while (!g_stop) {
    std::uint64_t next = bus.now_us() + 10000;  // wake at least every 10 ms
    for (auto& d : drives) next = std::min(next, std::max(d->next_event_us(), bus.now_us()));
    kerf::hal::CanFrame f;
    const auto r = bus.receive(f, next);
    const std::uint64_t now = bus.now_us();
    if (r == kerf::hal::CanResult::ok) {
      last_frame_us = now;
      if (f.id == kerf::hal::canopen::kSync) ++syncs;
      if (!injected && syncs >= fault_after_syncs && f.id == kerf::hal::canopen::kSync) {
        injected = true;
        for (auto& d : drives)
          if (d->node() == fault_node)
            d->inject(fault == "heartbeat-loss" ? kerf::sim::DriveFault::heartbeat_loss
                      : fault == "emcy"          ? kerf::sim::DriveFault::emcy
                                                 : kerf::sim::DriveFault::enable_refused,
                      now);
      }
      for (auto& d : drives) d->handle(f, now);
    } else if (r != kerf::hal::CanResult::timeout) {
      std::fprintf(stderr, "kerf-drive-sim: %s\n", bus.last_error());
      return 1;
    }
    for (auto& d : drives) d->tick(now);
    if (idle_exit_ms > 0 && syncs > 0 && now - last_frame_us > static_cast<std::uint64_t>(idle_exit_ms) * 1000u) break;
  }
  if (log) log->flush();
  std::fprintf(stderr, "kerf-drive-sim: %ld SYNCs seen\n", syncs);
  return 0;
}
