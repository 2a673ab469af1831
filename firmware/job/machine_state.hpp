// What the machine keeps between runs, like LinuxCNC's parameter file: the
// work offsets G54..G59.3 (set with G10 L2/L20), the G92 offset, and which
// coordinate system is selected. One small text file of `key = values`
// lines, written atomically (a temporary file, fsync, rename). Keys kerf does
// not know are kept as read and written back, so a later release can add its
// own without breaking an older file. `kerf home` adds the homed axes and
// the position (homed = x y, position = x y z).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace kerf::job {

inline constexpr int kCoordSystems = 9;  // G54 G55 G56 G57 G58 G59 G59.1 G59.2 G59.3

struct MachineState {
  double g5x[kCoordSystems][3] = {};  // mm, x y z of each system
  int coord = 0;                      // selected system: 0 = G54 ... 8 = G59.3
  double g92[3] = {};                 // mm
  bool g92_on = false;                // applied (G92, G92.3) or not (G92.1, G92.2)
  bool homed[3] = {};                 // x y z homed by `kerf home` (key `homed = x y`)
  bool has_position = false;          // `position = x y z`: machine position after the last session
  double position[3] = {};            // mm
  std::vector<std::pair<std::string, std::string>> other;  // unknown keys, as read
};

// The G-code name of system k (0..8): "G54" ... "G59.3".
const char* coord_name(int k);

// "x y" for the homed axes of n; empty when none.
std::string homed_names(const MachineState& s, int n);
// True when the first n axes are homed.
bool all_homed(const MachineState& s, int n);

// Reads `path`. A missing file is the default state (true): a new machine.
// False with "FILE:LINE: reason" for a file that is there but unreadable or malformed.
bool load_machine_state(const std::string& path, MachineState& out, std::string& error);
// Writes `path` atomically. False with a reason.
bool save_machine_state(const std::string& path, const MachineState& s, std::string& error);
std::string format_machine_state(const MachineState& s);

}  // namespace kerf::job
