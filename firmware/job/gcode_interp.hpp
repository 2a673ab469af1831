// The G-code interpreter: the RS274/NGC subset that 2-D cutting posts emit,
// with LinuxCNC's meaning, turned into canonical moves and actions (like
// LinuxCNC's canon calls) in machine coordinates and mm. It reads the
// blocks of the shared reader (job/gcode_reader.hpp), which `kerf weld`
// keeps using unchanged.
//
// Supported, per block in LinuxCNC's order of execution: F, S, T, M6, M3/M4/M5,
// M7/M8/M9, M62..M68, M100..M199, G4, G17 (G18/G19 refused), G20/G21,
// G40 (G41/G42 refused), G49, G54..G59.3, G61/G61.1/G64 [P Q], G90/G91,
// G90.1/G91.1, G10 L2/L20, G53, G92/G92.1/G92.2/G92.3, G80, G94 (G93/G95
// refused), G0/G1/G2/G3, then M0/M1/M2/M30; QtPlasmaC's M52 (recorded) and
// M190 P (material). Parameters, expressions and O-words are run by
// job/gcode_flow.hpp. Everything else (A/B/C/U/V/W axes, E words outside
// M66..M68, other G and M codes) is refused with FILE:LINE and its name.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "job/gcode_reader.hpp"
#include "job/machine_state.hpp"

namespace kerf::job {

enum class CanonKind : std::uint8_t {
  traverse,     // G0, G53 G0
  feed,         // G1
  arc,          // G2/G3
  dwell,        // G4 P: value = s
  pause,        // M0/M1
  end,          // M2/M30
  torch,        // M3/M4 (index 1) M5 (index 0), or the output named the torch
  digital_out,  // M62..M65, M7/M8/M9 and user M-codes: index, value 0/1, sync
  analog_out,   // M67/M68: index, value, sync
  wait_input,   // M66: index (digital P), mode (L), value = timeout s
  tool,         // M6: index = tool number
  feed_percent, // M67 E3 Q (QtPlasmaC): value = %
  tolerance,    // G64 P: value = the path tolerance in mm (capped by fit.tol)
};
const char* to_string(CanonKind k);

struct Canon {
  CanonKind kind = CanonKind::feed;
  std::size_t line = 0;
  double end[3] = {0, 0, 0};   // moves: machine mm
  double centre[2] = {0, 0};   // arcs: machine mm
  bool ccw = false;
  double feed_mm_min = 0;      // feed moves and arcs: programmed F (mm/min), 0 if none yet
  int index = 0;
  int mode = 0;
  double value = 0;
  bool sync = false;           // with motion (M62/M63/M67) or immediate (M64/M65/M68)
};

// A user M-code's configured action.
struct UserMcode {
  enum class Action : std::uint8_t { on, off, dwell, ignore };
  Action action = Action::ignore;
  int output = 0;     // on/off
  double seconds = 0; // dwell
};

struct Material {
  std::string name;
  double feed_mm_min = 0;      // 0: keep
  double pierce_delay_s = -1;  // < 0: keep
};

struct InterpSettings {
  double start[2] = {0, 0};   // the machine's position before the first move (mm)
  double fit_tol = 0.025;     // caps G64 P
  std::map<int, Material> tool_material;
  std::map<int, UserMcode> mcodes;  // by M number, 100..199
  bool strict_mcodes = false; // kerf run: an unconfigured user M-code refuses the job
  int torch_output = -1;      // an M62..M65 P number that is the torch; -1: none
  int mist_output = -1;       // M7
  int flood_output = -1;      // M8
  double cut_feed = 3000;     // mm/min: [cut] feed, what #<_hal[plasmac.cut-feed-rate]> reads with no material
  std::size_t max_blocks = 2'000'000;  // blocks that loops run beyond the file's own before it is refused
  bool z_axis = false;        // the machine has a z axis: Z runs as moves (job/gcode_program.hpp)
};

// How a construct was handled, for the run report.
struct Construct {
  std::string handling;  // run | recorded | ignored
  std::size_t count = 0;
  std::size_t first_line = 0;
};

struct Interpretation {
  std::vector<Canon> canon;
  std::map<std::string, Construct> constructs;  // "G54", "M6", "G64 P" ...
  std::vector<std::string> notes;               // once each: unmapped tools, unconfigured M-codes
  std::map<int, std::size_t> analog_inputs;     // M66 E (L0, read and ignored): number -> first line
  MachineState state;                           // offsets after the program
};

// Interprets `g` (already read without error) from the machine state
// `state` (offsets) into `out`. False with "FILE:LINE: reason" in `error`.
bool interpret(const GcodeFile& g, const InterpSettings& settings, const MachineState& state, Interpretation& out,
               std::string& error);

// The canonical moves and actions as text, one a line (the interpreter goldens, tests/interp).
std::string format_canon(const Interpretation& it);

}  // namespace kerf::job
