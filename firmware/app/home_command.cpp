#include "app/home_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "io/options.hpp"
#include "machine/homing.hpp"
#include "machine/machine_factory.hpp"

namespace kerf::app {

CLI::App* add_home_command(CLI::App& app, HomeOptions& o) {
  CLI::App* h = app.add_subcommand(
      "home", "Home the axes: the board (Modbus) or the drives (CAN) search their switches; the homed axes and the "
              "position go into the machine state file ([machine] state), where kerf run looks for them");
  h->add_option("--config", o.config, "Machine configuration (TOML)")->type_name("FILE")->required();
  h->add_option("--axis", o.axes, "An axis to home (x, y or z; repeat for several); default every axis, z first")
      ->check(CLI::IsMember({"x", "y", "z"}));
  return h;
}

int home_job(const HomeOptions& opts, const char* who, RunCheck check, LinesOpener open_lines, LinkOpener open_link) {
  std::string error;
  config::Config cfg;
  if (!config::load(opts.config, cfg, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return io::kExitUsage;
  }
  if (!check(cfg, error)) {
    std::fprintf(stderr, "%s: home: %s\n", who, error.c_str());
    return io::kExitFailure;
  }
  if (cfg.machine.state.empty()) {
    std::fprintf(stderr, "%s: home: %s: machine.state: needed to keep the homed axes for kerf run\n", who,
                 cfg.file.c_str());
    return io::kExitUsage;
  }
  // Default: every axis of the machine (home_axes takes z first).
  unsigned axes = opts.axes.empty() ? (1u << cfg.machine.axes.size()) - 1u : 0u;
  for (const std::string& a : opts.axes) {
    const unsigned bit = a == "x" ? 0u : a == "y" ? 1u : 2u;
    if (bit >= cfg.machine.axes.size()) {
      std::fprintf(stderr, "%s: home: --axis %s: the machine has no such axis\n", who, a.c_str());
      return io::kExitUsage;
    }
    axes |= 1u << bit;
  }
  job::MachineState state;
  if (!job::load_machine_state(cfg.machine.state, state, error)) {
    std::fprintf(stderr, "%s: home: machine.state: %s\n", who, error.c_str());
    return io::kExitUsage;
  }
  std::unique_ptr<hal::Gpio> gpio = open_lines(cfg, error);
  if (!gpio) {
    std::fprintf(stderr, "%s: home: %s\n", who, error.c_str());
    return io::kExitFailure;
  }
  hal::GpioInputs in;
  if (!gpio->read(0.0, in) || in.estop) {
    std::fprintf(stderr, "%s: home: the E-stop is asserted: nothing moves\n", who);
    return io::kExitFailure;
  }
  std::unique_ptr<hal::SegmentLink> link =
      open_link != nullptr ? open_link(cfg, opts, error) : machine::open_link(cfg, error);
  if (!link) {
    std::fprintf(stderr, "%s: home: %s: %s\n", who, config::to_string(cfg.link.kind), error.c_str());
    return io::kExitFailure;
  }
  const bool ok = machine::home_axes(cfg, axes, *link, gpio.get(), state, error, stdout);
  std::string saved;
  if (!job::save_machine_state(cfg.machine.state, state, saved)) {
    std::fprintf(stderr, "%s: home: machine.state: %s\n", who, saved.c_str());
    return io::kExitFailure;
  }
  if (!ok) {
    std::fprintf(stderr, "%s: home: %s\n", who, error.c_str());
    return io::kExitFailure;
  }
  if (cfg.machine.axes.size() > 2)
    std::printf("%s home: homed %s; position %.3f %.3f %.3f\n", who, job::homed_names(state, 3).c_str(),
                state.position[0], state.position[1], state.position[2]);
  else
    std::printf("%s home: homed %s; position %.3f %.3f\n", who, job::homed_names(state, 3).c_str(), state.position[0],
                state.position[1]);
  return io::kExitOk;
}

}  // namespace kerf::app
