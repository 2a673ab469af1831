// A G-code file as a job for `kerf sim` / `kerf run`: the interpreter's
// canonical moves (job/gcode_interp.hpp) turned into cut paths (XY points in
// machine mm, arcs sampled to a 0.001 mm chord) and the actions between them.
//
// A path is a run of feed moves (G1 G2 G3) with the torch on (M3/M4, or the
// output configured as the torch); a file with no torch word is a dry run:
// every feed move is in a path, and the torch stays off. A path ends at a
// rapid, at torch off, at a move that changes Z (a Z move never becomes an
// XY segment), and at every action (dwell, pause, output, wait, tool change,
// end): the action runs at rest between the paths.
//
// Z. Without a z axis (the default) Z is not driven: nothing else happens.
// With one (InterpSettings::z_axis) Z runs as moves at rest, never
// interpolated with XY (a thermal cutter moves Z between cuts; the height
// during a cut is the THC's). The moves between two paths are kept in
// program order (ProgramMove): XY rapids and z moves, a move that changes XY
// and Z together split into Z then XY when Z rises and XY then Z when it
// falls. Those before the first action after a path run right after it
// (ProgramPath::after: the retract comes before a tool change); the rest
// lead to the next path (ProgramPath::before). A feed move that changes Z
// with the torch on (a helical ramp) ends the path, runs Z at rest, then cuts
// its XY as the first move of the next path (the torch goes off for the Z
// move and the next path is pierced again).
// Each point carries the feed of the move that reaches it (programmed F, or
// the material's, times QtPlasmaC's `M67 E3` feed %), so a feed change inside
// a path neither splits it nor waits for the next one. Each path carries the
// tolerance (G64 P) and pierce delay (material) in force at its first move.
#pragma once

#include <string>
#include <vector>

#include "io/point_file.hpp"
#include "job/gcode_interp.hpp"

namespace kerf::job {

// With a z axis: a move between paths, at rest with the torch off.
struct ProgramMove {
  bool z = false;          // a z move (to z_end at xy); otherwise an XY rapid to xy
  Vec2<double> xy{};       // machine mm
  double z_end = 0;        // mm
  double feed_mm_min = 0;  // a z move's programmed feed (G1); 0: rapid
  std::size_t line = 0;
};

struct ProgramPath {
  bool torch = true;          // false: a dry-run path (torch off)
  double feed_mm_min = 0;     // at its first move; 0: the configuration's cut feed
  double pierce_delay_s = -1; // < 0: the configuration's
  double tol = 0;             // 0: the fit's
  std::vector<ProgramMove> before;  // z axis: the moves that lead to its first point
  std::vector<ProgramMove> after;   // z axis: the moves right after it (before the next action)
};

struct ProgramAction {
  CanonKind kind = CanonKind::dwell;  // dwell, pause, end, digital_out, analog_out, wait_input, tool
  std::size_t before_path = 0;        // runs before this path (paths.size(): after the last)
  std::size_t line = 0;
  int index = 0, mode = 0;
  double value = 0;
  bool sync = false;
  Vec2<double> at{};                  // where the machine is when it runs
};

struct GcodeProgram {
  io::PointFile points;               // the paths' points (path_begin) with their source lines
  std::vector<double> point_feed;     // mm/min for each point (0: the configuration's cut feed)
  std::vector<ProgramPath> paths;
  std::vector<ProgramAction> actions; // in program order
  Interpretation interp;              // its constructs, notes and final state (canon left empty)
  bool dry_run = false;               // no torch word in the file
  std::size_t z_moves = 0;            // z axis: the z moves in before/after
  double final_z = 0;                 // mm, Z at the program's end
};

// The program of an interpreted file. False with "FILE: reason" (no path to cut).
bool build_program(const GcodeFile& g, const InterpSettings& settings, const Interpretation& it, GcodeProgram& out,
                   std::string& error);

// read_gcode + interpret + build_program. False with "FILE:LINE: reason".
bool read_gcode_program(const std::string& path, const InterpSettings& settings, const MachineState& state,
                        GcodeProgram& out, std::string& error);

}  // namespace kerf::job
