// The interpreter goldens (LinuxCNC tests/interp style): each folder under
// tests/interp holds input.ngc and expected.txt, the canonical moves and
// actions (job::format_canon), then the program the controller runs (paths
// and actions), or the error. An optional state.txt is the machine state
// the program starts from; a file z_axis runs the case on a machine with a
// z axis. KERF_UPDATE_GOLDENS=1 rewrites expected.txt.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

#include "job/gcode_program.hpp"
#include "../support/interp_settings.hpp"

namespace {

namespace fs = std::filesystem;
using namespace kerf::job;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The settings every case runs with (tests/support/interp_settings.hpp).
InterpSettings settings() { return kerf_test::interp_case_settings(); }

std::string f4(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.4f", std::abs(v) < 5e-5 ? 0.0 : v);
  return buf;
}

std::string format_program(const GcodeProgram& p) {
  std::string s;
  std::size_t a = 0;
  auto actions_before = [&](std::size_t path) {
    for (; a < p.actions.size() && p.actions[a].before_path == path; ++a)
      s += "  ACTION " + std::string(to_string(p.actions[a].kind)) + " line " + std::to_string(p.actions[a].line) +
           " at " + f4(p.actions[a].at.x) + " " + f4(p.actions[a].at.y) + "\n";
  };
  s += std::string("PROGRAM") + (p.dry_run ? " dry-run" : "") + "\n";
  // z axis: the moves between paths (none without one).
  auto moves = [&](const char* when, const std::vector<ProgramMove>& v) {
    for (const ProgramMove& m : v)
      s += std::string("    ") + when + (m.z ? " Z " + f4(m.z_end) + " at " : " XY ") + f4(m.xy.x) + " " +
           f4(m.xy.y) + (m.feed_mm_min > 0 ? " F" + f4(m.feed_mm_min) : " rapid") + " line " +
           std::to_string(m.line) + "\n";
  };
  for (std::size_t k = 0; k < p.paths.size(); ++k) {
    actions_before(k);
    const std::size_t b = p.points.path_begin[k];
    const std::size_t e = k + 1 < p.paths.size() ? p.points.path_begin[k + 1] : p.points.points.size();
    const ProgramPath& pp = p.paths[k];
    moves("BEFORE", pp.before);
    double lo = 1e300, hi = 0;  // the feeds along the path
    for (std::size_t i = b; i < e; ++i) lo = std::min(lo, p.point_feed[i]), hi = std::max(hi, p.point_feed[i]);
    s += "  PATH " + std::string(pp.torch ? "torch" : "dry") + " feed " + f4(pp.feed_mm_min) +
         (lo != hi ? " (" + f4(lo) + ".." + f4(hi) + ")" : "") + " tol " + f4(pp.tol) +
         " pierce " + f4(pp.pierce_delay_s) + " points " + std::to_string(e - b) + " from " +
         f4(p.points.points[b].x) + " " + f4(p.points.points[b].y) + " to " + f4(p.points.points[e - 1].x) + " " +
         f4(p.points.points[e - 1].y) + " lines " + std::to_string(p.points.point_lines[b]) + ".." +
         std::to_string(p.points.point_lines[e - 1]) + "\n";
    moves("AFTER", pp.after);
  }
  actions_before(p.paths.size());
  if (p.z_moves > 0) s += "  Z MOVES " + std::to_string(p.z_moves) + " final z " + f4(p.final_z) + "\n";
  for (const char* name : {"Z move", "Z with the torch on"}) {
    const auto c = p.interp.constructs.find(name);
    if (c != p.interp.constructs.end())
      s += std::string("  CONSTRUCT ") + name + ": " + c->second.handling + " (" + std::to_string(c->second.count) +
           ", first line " + std::to_string(c->second.first_line) + ")\n";
  }
  return s;
}

std::string run_case(const fs::path& dir) {
  MachineState state;
  std::string error;
  if (fs::exists(dir / "state.txt") && !load_machine_state((dir / "state.txt").string(), state, error))
    return "ERROR " + error + "\n";
  const GcodeFile g = parse_gcode(slurp(dir / "input.ngc"), "input.ngc");
  InterpSettings set = settings();
  set.z_axis = fs::exists(dir / "z_axis");  // the case's machine has a z axis
  Interpretation it;
  if (!interpret(g, set, state, it, error)) return "ERROR " + error + "\n";
  GcodeProgram prog;
  std::string out = format_canon(it);
  if (!build_program(g, set, it, prog, error)) return out + "PROGRAM ERROR " + error + "\n";
  return out + format_program(prog);
}

TEST(InterpGoldens, EveryCaseMatches) {
  const fs::path root = KERF_INTERP_DIR;
  std::size_t cases = 0;
  const bool update = std::getenv("KERF_UPDATE_GOLDENS") != nullptr;
  for (const fs::directory_entry& d : fs::directory_iterator(root)) {
    if (!d.is_directory() || !fs::exists(d.path() / "input.ngc")) continue;
    ++cases;
    const std::string got = run_case(d.path());
    if (update) {
      std::ofstream(d.path() / "expected.txt", std::ios::binary) << got;
      continue;
    }
    EXPECT_EQ(got, slurp(d.path() / "expected.txt")) << "case " << d.path().filename();
  }
  EXPECT_GE(cases, 20u);
}

// Offsets are kept across runs: a second run starts from the state the
// first left, through the state file (written atomically, read back).
TEST(InterpState, OffsetsKeptAcrossRunsThroughTheStateFile) {
  const std::string path = ::testing::TempDir() + "kerf_interp_state.txt";
  std::remove(path.c_str());
  MachineState s;
  std::string error;
  ASSERT_TRUE(load_machine_state(path, s, error)) << error;  // none yet: a new machine
  Interpretation first;
  ASSERT_TRUE(interpret(parse_gcode("G10 L2 P2 X100 Y50\nG55\nG92 X0 Y0\nM2\n", "a.ngc"), settings(), s, first, error));
  s = first.state;
  s.other.emplace_back("tool_life", "1");  // a key of a later release: kept as written
  ASSERT_TRUE(save_machine_state(path, s, error)) << error;
  MachineState back;
  ASSERT_TRUE(load_machine_state(path, back, error)) << error;
  EXPECT_EQ(back.coord, 0);  // M2 selected G54 again
  EXPECT_EQ(back.g5x[1][0], 100.0);
  EXPECT_EQ(back.g5x[1][1], 50.0);
  EXPECT_TRUE(back.g92_on);
  ASSERT_EQ(back.other.size(), 1u);
  EXPECT_EQ(back.other[0].first, "tool_life");
  Interpretation second;
  ASSERT_TRUE(interpret(parse_gcode("G55 G1 X1 Y2 F100\n", "b.ngc"), settings(), back, second, error));
  ASSERT_EQ(second.canon.size(), 1u);
  // G55 (100, 50) plus the G92 offset: G92 X0 Y0 at the origin under G55 made it (-100, -50).
  EXPECT_DOUBLE_EQ(second.canon[0].end[0], 1.0);
  EXPECT_DOUBLE_EQ(second.canon[0].end[1], 2.0);
  std::remove(path.c_str());
}

TEST(InterpState, AMalformedStateFileIsRefusedWithItsLine) {
  const std::string path = ::testing::TempDir() + "kerf_interp_bad_state.txt";
  std::ofstream(path) << "# state\nG54 = 1 2\n";
  MachineState s;
  std::string error;
  EXPECT_FALSE(load_machine_state(path, s, error));
  EXPECT_EQ(error, path + ":2: G54: expected three numbers (x y z mm)");
  std::remove(path.c_str());
}

TEST(InterpStrict, KerfRunRefusesAnUnconfiguredUserMcodeWithTheKeyToAdd) {
  InterpSettings s = settings();
  s.strict_mcodes = true;
  Interpretation it;
  std::string error;
  EXPECT_FALSE(interpret(parse_gcode("G0 X0 Y0\nM150\n", "u.ngc"), s, MachineState{}, it, error));
  EXPECT_EQ(error, "u.ngc:2: M150 is a user M-code with no action: add [mcodes.M150] with action = \"on\", \"off\", "
                   "\"dwell\" or \"ignore\" to the configuration");
}

// The loop cap counts only what loops run again: a straight file longer than
// the cap runs (a 10-million-line laser job is a correct program), while the
// same cap still stops a loop (the loop_cap golden).
TEST(InterpLoopCap, AStraightFileLongerThanTheCapRuns) {
  InterpSettings s = settings();
  s.max_blocks = 1000;
  std::string text = "G0 X0 Y0\nM3\n";
  for (int i = 1; i <= 3000; ++i) text += "G1 X" + std::to_string(i % 50) + " Y" + std::to_string(i % 7) + " F600\n";
  Interpretation it;
  std::string error;
  ASSERT_TRUE(interpret(parse_gcode(text, "long.ngc"), s, MachineState{}, it, error)) << error;
  EXPECT_GE(it.canon.size(), 3000u);
  Interpretation looped;
  EXPECT_FALSE(interpret(parse_gcode("o1 while [1]\nG1 X1 F600\no1 endwhile\n", "w.ngc"), s, MachineState{}, looped, error));
  EXPECT_NE(error.find("w.ngc:"), std::string::npos) << error;
}

}  // namespace
