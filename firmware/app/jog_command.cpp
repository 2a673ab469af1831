#include "app/jog_command.hpp"

#include <CLI/CLI.hpp>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>

#include "control/soft_limits.hpp"
#include "io/options.hpp"
#include "machine/jog.hpp"
#include "machine/machine_factory.hpp"

namespace kerf::app {

namespace {

// What both sessions open: the configuration, its state file, the lines and the link.
struct Session {
  config::Config cfg;
  job::MachineState state;
  std::unique_ptr<hal::Gpio> gpio;
  std::unique_ptr<hal::SegmentLink> link;
  hal::BoardStatus st;  // the board's status when the session opened
};

int open_session(const std::string& file, const char* who, const char* what, RunCheck check,
                 LinesOpener open_lines, Session& s) {
  std::string error;
  if (!config::load(file, s.cfg, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return io::kExitUsage;
  }
  if (!check(s.cfg, error)) {
    std::fprintf(stderr, "%s: %s: %s\n", who, what, error.c_str());
    return io::kExitFailure;
  }
  if (s.cfg.machine.state.empty()) {
    std::fprintf(stderr, "%s: %s: %s: machine.state: needed (the homed axes and the offsets are kept there)\n", who,
                 what, s.cfg.file.c_str());
    return io::kExitUsage;
  }
  if (!job::load_machine_state(s.cfg.machine.state, s.state, error)) {
    std::fprintf(stderr, "%s: %s: machine.state: %s\n", who, what, error.c_str());
    return io::kExitUsage;
  }
  // Refused before anything opens: a jog or touch-off needs a known position,
  // on every axis (an unhomed z could hold the torch anywhere).
  if (!job::all_homed(s.state, std::max(2, static_cast<int>(s.cfg.machine.axes.size())))) {
    std::fprintf(stderr, "%s: %s: the machine is not homed: run `kerf home` first\n", who, what);
    return io::kExitFailure;
  }
  s.gpio = open_lines(s.cfg, error);
  if (!s.gpio) {
    std::fprintf(stderr, "%s: %s: %s\n", who, what, error.c_str());
    return io::kExitFailure;
  }
  hal::GpioInputs in;
  if (!s.gpio->read(0.0, in) || in.estop) {
    std::fprintf(stderr, "%s: %s: the E-stop is asserted: nothing moves\n", who, what);
    return io::kExitFailure;
  }
  s.link = machine::open_link(s.cfg, error);
  if (!s.link) {
    std::fprintf(stderr, "%s: %s: %s: %s\n", who, what, config::to_string(s.cfg.link.kind), error.c_str());
    return io::kExitFailure;
  }
  if (s.link->status(s.st) != hal::LinkError::none) {
    std::fprintf(stderr, "%s: %s: cannot read the board: %s\n", who, what, s.link->last_error());
    return io::kExitFailure;
  }
  return io::kExitOk;
}

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_interrupt(int) { g_interrupted = 1; }

// The operator lets go of a continuous jog: SIGINT (Ctrl-C), or stdin gives
// a line or closes (an operator interface holds the jog by keeping its pipe
// open, as a pendant holds the button).
bool operator_released() {
  static bool installed = false;
  if (!installed) {
    installed = true;
    struct sigaction sa {};
    sa.sa_handler = on_interrupt;
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
  }
  if (g_interrupted != 0) return true;
  pollfd p{STDIN_FILENO, POLLIN, 0};
  if (::poll(&p, 1, 0) <= 0) return false;
  return (p.revents & (POLLIN | POLLHUP | POLLERR | POLLNVAL)) != 0;  // a key, or EOF
}

void keep_position(job::MachineState& s, Vec2<double> at) {
  s.has_position = true;
  s.position[0] = at.x;
  s.position[1] = at.y;
}

}  // namespace

CLI::App* add_jog_command(CLI::App& app, JogOptions& o) {
  CLI::App* j = app.add_subcommand("jog", "Jog one axis at [machine] jog_speed: by --distance, --to a machine "
                                          "position, or --continuous until released; refused before homing, stopped "
                                          "by the E-stop");
  j->add_option("--config", o.config, "Machine configuration (TOML)")->type_name("FILE")->required();
  j->add_option("--axis", o.axis, "x or y")->check(CLI::IsMember({"x", "y"}));
  auto* d = j->add_option("--distance", o.distance, "Incremental move, mm (signed)");
  auto* t = j->add_option("--to", o.to, "Absolute machine position, mm");
  auto* c = j->add_option("--continuous", o.continuous,
                          "Jog in this direction until released (Enter, stdin closed, or Ctrl-C), at most to the "
                          "axis's soft limit")
                ->check(CLI::IsMember({"+", "-"}));
  d->excludes(t);
  c->excludes(d)->excludes(t);
  j->callback([&o, d, t] {
    o.has_distance = d->count() > 0;
    o.has_to = t->count() > 0;
  });
  return j;
}

CLI::App* add_touch_off_command(CLI::App& app, TouchOffOptions& o) {
  CLI::App* t = app.add_subcommand("touch-off", "Set the active work offset (G54 ...) so that where the torch stands "
                                                "becomes X0 Y0 (as G10 L20 P0 X0 Y0); kept in the state file");
  t->add_option("--config", o.config, "Machine configuration (TOML)")->type_name("FILE")->required();
  return t;
}

int jog_job(JogOptions opts, const char* who, RunCheck check, LinesOpener open_lines) {
  const bool continuous = !opts.continuous.empty();
  if (!continuous && opts.has_distance == opts.has_to)
    return io::usage_error("jog: give --distance, --to or --continuous");
  Session s;
  if (const int rc = open_session(opts.config, who, "jog", check, open_lines, s); rc != io::kExitOk) return rc;
  const motion::SoftLimits<double> limits = control::soft_limits_of(s.cfg.machine);
  const int axis = opts.axis == "x" ? 0 : 1;
  Vec2<double> to = s.st.position;
  if (continuous && !machine::continuous_target(s.st.position, axis, opts.continuous == "+" ? 1 : -1, limits, to)) {
    std::fprintf(stderr, "%s: jog: %s: machine.axis: --continuous needs min and max on axis %s (it must end "
                         "somewhere)\n", who, s.cfg.file.c_str(), opts.axis.c_str());
    return io::kExitUsage;
  }
  if (!continuous) {
    double& v = axis == 0 ? to.x : to.y;
    v = opts.has_to ? opts.to : v + opts.distance;
    if (machine::clamp_to_limits(to, limits))
      std::fprintf(stderr, "%s: jog: stops at the soft limit: %.3f %.3f\n", who, to.x, to.y);
  }
  const double feed = std::min(s.cfg.machine.jog_speed, s.cfg.machine.rapid_feed) / 60.0;
  Vec2<double> at{};
  std::string error;
  const bool ok = continuous
                      ? machine::jog_until_released(*s.link, s.gpio.get(), to, feed, operator_released, at, error)
                      : machine::jog_to(*s.link, s.gpio.get(), to, feed, at, error);
  keep_position(s.state, at);
  std::string saved;
  if (!job::save_machine_state(s.cfg.machine.state, s.state, saved)) {
    std::fprintf(stderr, "%s: jog: machine.state: %s\n", who, saved.c_str());
    return io::kExitFailure;
  }
  if (!ok) {
    std::fprintf(stderr, "%s: jog: %s; the axes stand at %.3f %.3f\n", who, error.c_str(), at.x, at.y);
    return io::kExitFailure;
  }
  if (continuous)
    std::printf("%s jog: %s\n", who, std::hypot(at.x - to.x, at.y - to.y) < 0.001 ? "stopped at the soft limit"
                                                                                    : "released");
  std::printf("%s jog: at %.3f %.3f\n", who, at.x, at.y);
  return io::kExitOk;
}

int touch_off_job(const TouchOffOptions& opts, const char* who, RunCheck check, LinesOpener open_lines) {
  Session s;
  if (const int rc = open_session(opts.config, who, "touch-off", check, open_lines, s); rc != io::kExitOk) return rc;
  const hal::BoardStatus& st = s.st;
  machine::touch_off(s.state, st.position);
  keep_position(s.state, st.position);
  std::string error;
  if (!job::save_machine_state(s.cfg.machine.state, s.state, error)) {
    std::fprintf(stderr, "%s: touch-off: machine.state: %s\n", who, error.c_str());
    return io::kExitFailure;
  }
  std::printf("%s touch-off: %s = %.3f %.3f (the torch at %.3f %.3f is X0 Y0)\n", who, job::coord_name(s.state.coord),
              s.state.g5x[s.state.coord][0], s.state.g5x[s.state.coord][1], st.position.x, st.position.y);
  return io::kExitOk;
}

}  // namespace kerf::app
