// The machine configuration, read from a TOML file (toml++). Every value has
// a default except where a machine cannot do without one (the link). A bad
// value is refused with "FILE:LINE: KEY: reason"; unknown keys are refused
// too, so a typo never silently leaves a default in place.
// firmware/examples/kerf.toml is the commented example.
#pragma once

#include "config/cut_rules.hpp"
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "job/criterion.hpp"
#include "job/gcode_interp.hpp"
#include "kerf/hal/gpio.hpp"
#include "kerf/motion/axis_move.hpp"

namespace kerf::config {

struct Axis {
  std::string name;            // "x", "y", "z"
  double counts_per_mm = 1000; // > 0; required in each [[machine.axis]] of a file
  // z only (z moves run alone, at rest in XY): mm/min and mm/s^2, > 0;
  // absent: machine.rapid_feed and machine.accel.
  double feed = 0, accel = 0;
  // Soft limits, mm in machine coordinates (min < max); absent: unlimited on
  // that side. A real table sets both: jobs are checked against them before
  // the torch fires (control/soft_limits.hpp), and kerf run warns without them.
  bool has_min = false, has_max = false;
  double min = 0, max = 0;
  // Homing (keys home_* on [[machine.axis]]; the board's own switch input).
  // Speeds mm/min, lengths mm; dir -1: the switch lies towards negative
  // (z's default is +1: a torch homes up).
  int home_dir = -1;
  double home_search_speed = 1200, home_latch_speed = 60;
  double home_search_distance = 2000, home_backoff = 2, home_position = 0;
  // The switch on a GPIO line: a [[gpio.input]] number (home_input); kerf
  // searches it with jog moves and sets the board's position (machine/
  // homing_gpio.hpp). -1: the board's or drive's own input.
  int home_input = -1;
};

struct Machine {
  std::vector<Axis> axes;      // 2 or 3; default x and y at 1000 counts/mm
  double max_feed = 10000;     // mm/min, > 0: cut and rapid feeds are capped by it
  double rapid_feed = 10000;   // mm/min, > 0, <= max_feed; absent from a file: max_feed
  double accel = 1000;         // mm/s^2, > 0
  double jerk = 0;             // mm/s^3, 0: trapezoidal ramps
  double servo_period = 0.001; // s, the board's interpolation period, (0, 0.1]
  double cycle = 0.002;        // s, the controller's loop period, (0, 0.1]
  std::string state;           // the machine state file (work offsets; job/machine_state.hpp); empty: none
  // Following error, mm, > 0 (LinuxCNC's FERROR/MIN_FERROR): the limit at
  // max_feed and at rest, linear in between; min_ferror <= ferror.
  double ferror = 1.0;
  double min_ferror = 0.25;
  // The machine has home switches: kerf run then refuses to start until
  // `kerf home` has homed every axis; false: --assume-homed may stand in.
  bool home_switches = true;
  double jog_speed = 1200;  // mm/min, > 0: kerf jog's feed (capped by rapid_feed)
};

// The z axis's limits (the servo period, feed mm/s, accel), or none
// (period 0) on a machine without one.
inline motion::AxisLimits<double> z_limits(const Machine& m) {
  if (m.axes.size() < 3) return {};
  const Axis& z = m.axes[2];
  return {m.servo_period, (z.feed > 0 ? z.feed : m.rapid_feed) / 60.0, z.accel > 0 ? z.accel : m.accel};
}

struct Link {
  enum class Kind : std::uint8_t { modbus_tcp, modbus_rtu, can };
  Kind kind = Kind::modbus_tcp;
  std::string host = "127.0.0.1";  // modbus-tcp
  int port = 502;                  // modbus-tcp, 1..65535
  std::string device;              // modbus-rtu (required), e.g. /dev/ttyUSB0
  int baud = 115200;               // modbus-rtu
  int unit = 17;                   // modbus unit id, 1..247
  std::string iface = "can0";      // can
  std::vector<int> node_ids;       // can (required), one per axis, 1..127, distinct
  double sync_ms = 1;              // can, SYNC period, 1..10
  double timeout = 1.0;            // s, give up when the link is down this long, > 0
};

struct Fit {
  job::Criterion criterion = job::Criterion::band;
  job::Numeric numeric = job::Numeric::floating;  // the fit's scalar type, for every criterion
  double tol = 0.025;              // mm, > 0
};

struct Cut {
  double feed = 3000;            // mm/min, > 0, <= machine.max_feed
  double pierce_delay = 0.5;     // s, >= 0
  double arc_ok_timeout = 3.0;   // s, > 0
  CutRules rules;                // holes, tight arcs, overcut, thc_lock (config/cut_rules.hpp)
};

// What the G-code interpreter takes from the configuration (config/program_section.cpp):
// [tools] N = "material", [materials.NAME] feed/pierce_delay, [mcodes.MNNN]
// action/output/seconds, [outputs] torch/mist/flood, [analog] ignore.
struct Program {
  std::map<int, job::Material> tool_material;
  std::map<int, job::UserMcode> mcodes;
  int torch_output = -1, mist_output = -1, flood_output = -1;
  std::vector<int> analog_ignore;  // analog numbers (M67/M68 E, M66 E) kerf run accepts and ignores
};

struct Sim {
  double operator_delay = 1.0;   // s, >= 0: the simulated operator presses cycle-start after a pause
  double start[2] = {0, 0};      // mm, where the simulated machine stands before the first move
};

struct Rt {
  int priority = 0;      // SCHED_FIFO priority 1..99; 0: do not ask
  bool lock_memory = false;
};

// A bench: the machine's axes without a torch. `kerf run` then runs motion
// only, refuses any torch output, and marks every status line and the report
// BENCH (machine/machine_factory.hpp).
struct Bench {
  bool enabled = false;
};

struct Config {
  std::string file;  // where it was read from; "(defaults)" for defaults()
  Machine machine;
  Link link;
  hal::GpioConfig gpio;
  Fit fit;
  Cut cut;
  Rt rt;
  Program program;
  Sim sim;
  Bench bench;
};

// The interpreter's settings from a configuration (strict: kerf run).
job::InterpSettings interp_settings(const Config& c, bool strict);

// The defaults above, as a config for the simulator (kerf sim without --config).
Config defaults();

// Reads and validates `path`. On failure returns false and sets `error` to
// "FILE:LINE: KEY: reason" (or "FILE: reason" for an unreadable file).
bool load(const std::string& path, Config& out, std::string& error);

// Parses TOML text; `display_name` labels errors.
bool parse(const std::string& text, const std::string& display_name, Config& out,
           std::string& error);

const char* to_string(Link::Kind k);

}  // namespace kerf::config
