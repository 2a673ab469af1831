#include "machine/homing.hpp"

#include <chrono>
#include <thread>

#include "machine/homing_gpio.hpp"

namespace kerf::machine {

namespace {

const char* const kAxis[3] = {"x", "y", "z"};
// z first: the torch goes up, clear of the sheet and the clamps, before x
// and y travel (LinuxCNC's HOME_SEQUENCE with z at 0 on a plasma table).
constexpr int kHomeOrder[3] = {2, 0, 1};

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool homing_runs(hal::HomingState s) {
  return s == hal::HomingState::search || s == hal::HomingState::backoff || s == hal::HomingState::latch;
}

// The longest a cycle can take: the search, the back-off twice over, the latch.
double cycle_limit_s(const hal::HomeCommand& h) {
  return (h.search_distance + 2 * h.backoff) / h.search_speed + (h.backoff + 1) / h.latch_speed + 5.0;
}

// A GPIO home switch needs its [[gpio.input]] and the Modbus board (which
// takes "here" as the home; CAN drives home on their own inputs).
bool gpio_switch_usable(const config::Config& cfg, int input, hal::Gpio* gpio, std::string& error) {
  bool configured = false;
  for (const hal::GpioProgramLine& l : cfg.gpio.inputs) configured = configured || l.number == input;
  if (!configured || gpio == nullptr) {
    error = cfg.file + ": machine.axis: home_input = " + std::to_string(input) + ": no [[gpio.input]] with that number";
    return false;
  }
  if (cfg.link.kind == config::Link::Kind::can) {
    error = cfg.file + ": machine.axis: home_input: a GPIO home switch needs the Modbus board; CAN drives home on "
                       "their own inputs (CiA 402 homing)";
    return false;
  }
  return true;
}

// t_start: the session's start, the scripted lines' time origin.
bool home_one(const config::Config& cfg, int a, hal::SegmentLink& link, hal::Gpio* gpio, double t_start,
              hal::BoardStatus& st, std::string& error, std::FILE* log) {
  hal::HomeCommand h = home_command(cfg.machine, a);
  const std::string who = std::string(kAxis[a]) + ": ";
  if (const int input = cfg.machine.axes[static_cast<std::size_t>(a)].home_input; input >= 0) {
    if (!gpio_switch_usable(cfg, input, gpio, error) || !search_gpio_switch(link, *gpio, h, input, h, error)) {
      error = who + error;
      return false;
    }
  }
  // The E-stop line: the Modbus board is aborted below while the host
  // polls; a CAN drive is halted by the master while home() runs.
  auto estop = [&] {
    hal::GpioInputs in;
    return gpio != nullptr && (!gpio->read(now_s() - t_start, in) || in.estop);
  };
  if (link.home(h, estop) != hal::LinkError::none) {
    error = who + "the board refused to home: " + link.last_error();
    return false;
  }
  const double t0 = now_s(), limit = cycle_limit_s(h);
  for (;;) {
    if (estop()) {
      link.command(hal::Command::abort);  // the board stops the axis, unhomed
      error = who + "E-stop: homing aborted, the axis is not homed";
      return false;
    }
    if (link.status(st) != hal::LinkError::none) {
      link.command(hal::Command::abort);
      error = who + "lost the board while homing: " + link.last_error();
      return false;
    }
    if (!homing_runs(st.homing)) break;
    if (now_s() - t0 > limit) {
      link.command(hal::Command::abort);
      error = who + "homing did not end within " + std::to_string(limit) + " s";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (st.homing != hal::HomingState::done || (st.homed & (1u << a)) == 0) {
    error = who + (st.homing == hal::HomingState::aborted && estop() ? "E-stop: homing aborted, the axis is not homed"
                                                                     : hal::to_string(st.homing));
    if (st.homing == hal::HomingState::no_switch)
      error += " (" + std::to_string(h.search_distance) + " mm at " + std::to_string(h.search_speed * 60) + " mm/min)";
    return false;
  }
  if (log != nullptr)
    std::fprintf(log, "home: %s homed at %.3f mm\n", kAxis[a], a == 0 ? st.position.x : a == 1 ? st.position.y : st.z);
  return true;
}

}  // namespace

hal::HomeCommand home_command(const config::Machine& m, int axis) {
  const config::Axis& x = m.axes[static_cast<std::size_t>(axis)];
  hal::HomeCommand h;
  h.axis = axis;
  h.dir = x.home_dir;
  h.search_speed = x.home_search_speed / 60.0;
  h.latch_speed = x.home_latch_speed / 60.0;
  h.search_distance = x.home_search_distance;
  h.backoff = x.home_backoff;
  h.home_position = x.home_position;
  return h;
}

bool home_axes(const config::Config& cfg, unsigned axes, hal::SegmentLink& link, hal::Gpio* gpio,
               job::MachineState& state, std::string& error, std::FILE* log) {
  hal::BoardStatus st;
  if (link.status(st) != hal::LinkError::none) {
    error = std::string("cannot read the board: ") + link.last_error();
    return false;
  }
  if (st.state == hal::BoardState::fault && link.command(hal::Command::fault_reset) != hal::LinkError::none) {
    error = std::string("the board is in fault and refused the reset: ") + link.last_error();
    return false;
  }
  const int n = static_cast<int>(cfg.machine.axes.size());
  const double t_start = now_s();
  bool ok = true;
  for (const int a : kHomeOrder) {
    if (!ok) break;
    if (a >= n || (axes & (1u << a)) == 0) continue;
    state.homed[a] = false;  // whatever happens now, the old flag no longer holds
    ok = home_one(cfg, a, link, gpio, t_start, st, error, log);
    state.homed[a] = ok;
  }
  if (link.status(st) == hal::LinkError::none) {
    state.has_position = true;
    state.position[0] = st.position.x;
    state.position[1] = st.position.y;
    state.position[2] = st.z;
  }
  return ok;
}

bool check_homed(const config::Config& cfg, const job::MachineState& state, bool assume_homed, std::string& error) {
  const int n = static_cast<int>(cfg.machine.axes.size());  // every axis, z too when there is one
  if (assume_homed) {
    if (cfg.machine.home_switches) {
      error = cfg.file + ": --assume-homed: the machine has home switches ([machine] home_switches = true): "
                         "home it with `kerf home`";
      return false;
    }
    return true;
  }
  if (cfg.machine.state.empty()) {
    error = cfg.file + ": machine.state: kerf run needs a state file to find the homed axes in (`kerf home` "
                       "writes it)";
    return false;
  }
  if (!job::all_homed(state, n)) {
    const std::string homed = job::homed_names(state, n);
    error = "the machine is not homed (" + (homed.empty() ? std::string("no axis") : "only " + homed) +
            " in " + cfg.machine.state + "): run `kerf home` first" +
            (cfg.machine.home_switches ? "" : ", or confirm the position with --assume-homed");
    return false;
  }
  return true;
}

bool check_board_homed(const job::MachineState& state, hal::SegmentLink& link, std::string& error) {
  hal::BoardStatus st;
  if (link.status(st) != hal::LinkError::none) {
    error = std::string("cannot read the board's homed state: ") + link.last_error();
    return false;
  }
  std::string lost;
  for (int a = 0; a < 3; ++a)
    if (state.homed[a] && (st.homed & (1u << a)) == 0) lost += lost.empty() ? kAxis[a] : std::string(" ") + kAxis[a];
  if (lost.empty()) return true;
  error = "the state file says homed, but the board says " + lost +
          " not homed since its power-up (was it power-cycled?): run `kerf home` again";
  return false;
}

}  // namespace kerf::machine
