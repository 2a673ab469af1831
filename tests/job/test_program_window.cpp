// The window reading of a G-code program (job/program_window.hpp) against
// the whole reading (WholeProgramStream over read_gcode_program): every
// corpus file, read in parts small enough that every line boundary is a
// part boundary, gives the same items bit for bit, the same summary, and the
// same error text.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <thread>

#include <sys/stat.h>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "job/program_window.hpp"
#include "program_dump.hpp"
#include "../support/interp_settings.hpp"

namespace {

namespace fs = std::filesystem;
using namespace kerf::job;
using kerf_test::Drained;

struct Reading {
  bool opened = false;
  std::string error;  // at open
  bool window = false;
  Drained d;
};

Reading read(const std::string& file, const InterpSettings& s, const MachineState& st, bool whole,
             std::size_t part_bytes) {
  Reading r;
  ProgramStreamOptions o;
  o.whole = whole;
  o.part_bytes = part_bytes;
  std::unique_ptr<ProgramStream> stream;
  r.opened = open_program_stream(file, s, st, o, stream, r.error);
  if (!r.opened) return r;
  r.window = dynamic_cast<WindowProgramStream*>(stream.get()) != nullptr;
  const bool dry = stream->dry_run();  // known before the first item
  r.d = kerf_test::drain(*stream);
  if (r.d.ok) {
    EXPECT_EQ(dry, stream->summary().dry_run) << file;
  }
  return r;
}

// The window reading of `file` is the whole reading's; true when it was a window reading.
bool expect_same(const std::string& file, const InterpSettings& s, const MachineState& st, std::size_t part_bytes) {
  const Reading w = read(file, s, st, true, 0);
  const Reading p = read(file, s, st, false, part_bytes);
  const std::string what = file + " in parts of " + std::to_string(part_bytes) + " bytes";
  if (!w.opened) {  // refused whole: refused at open, or met as the stream reaches it
    if (!p.opened) {
      EXPECT_EQ(p.error, w.error) << what;
    } else {
      EXPECT_EQ(p.d.tail, "ERROR " + w.error) << what;
    }
    return p.window;
  }
  EXPECT_TRUE(p.opened) << what << ": " << p.error;
  if (!p.opened) return false;
  EXPECT_EQ(p.d.items.size(), w.d.items.size()) << what;
  for (std::size_t k = 0; k < p.d.items.size() && k < w.d.items.size(); ++k)
    if (p.d.items[k] != w.d.items[k]) {
      ADD_FAILURE() << what << ": item " << k << "\nwindow:\n" << p.d.items[k] << "whole:\n" << w.d.items[k];
      break;
    }
  EXPECT_EQ(p.d.tail, w.d.tail) << what;
  return p.window;
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> v;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".ngc" || ext == ".nc" || ext == ".gcode")) v.push_back(e.path());
  }
  std::sort(v.begin(), v.end());
  return v;
}

TEST(ProgramWindow, EveryCorpusFileGivesWhatTheWholeReadingGives) {
  const fs::path tests = KERF_TESTS_DIR;
  std::size_t files = 0, windowed = 0;
  for (const char* dir : {"data/gcode", "data/print", "fuzz/corpus/gcode", "cli/bad_input", "cli/cases"})
    for (const fs::path& f : files_in(tests / dir)) {
      // Every line boundary a part boundary; the large files (up to 1.1 MB) once so.
      const bool small = fs::file_size(f) < 100000;
      const InterpSettings cases = kerf_test::interp_case_settings();
      InterpSettings plain, z_axis;
      z_axis.z_axis = true;
      windowed += expect_same(f.string(), cases, MachineState{}, 64);
      ++files;
      expect_same(f.string(), cases, MachineState{}, std::size_t{1} << 20);
      expect_same(f.string(), plain, MachineState{}, small ? 64 : 4096);
      if (!small) continue;
      expect_same(f.string(), z_axis, MachineState{}, 64);
      expect_same(f.string(), cases, MachineState{}, 1);
    }
  std::printf("%zu files, %zu read in a window (the rest have O-words)\n", files, windowed);
  EXPECT_GE(files, 60u);
  EXPECT_GE(windowed, files * 3 / 4) << "most files have no O-words: the window reads them";
}

// The interpreter goldens' inputs, with their machine state and z axis.
TEST(ProgramWindow, EveryInterpreterCaseGivesWhatTheWholeReadingGives) {
  std::size_t cases = 0;
  for (const fs::directory_entry& d : fs::directory_iterator(fs::path(KERF_TESTS_DIR) / "interp")) {
    const fs::path input = d.path() / "input.ngc";
    if (!d.is_directory() || !fs::exists(input)) continue;
    ++cases;
    MachineState st;
    std::string error;
    if (fs::exists(d.path() / "state.txt")) {
      ASSERT_TRUE(load_machine_state((d.path() / "state.txt").string(), st, error));
    }
    InterpSettings s = kerf_test::interp_case_settings();
    s.z_axis = fs::exists(d.path() / "z_axis");
    for (const std::size_t part : {std::size_t{1}, std::size_t{64}, std::size_t{4096}})
      expect_same(input.string(), s, st, part);
  }
  EXPECT_GE(cases, 30u);
}

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// What the reader refuses anywhere in the file is refused at open, as the whole reading does.
TEST(ProgramWindow, ALineThatDoesNotParseIsRefusedAtOpen) {
  const std::string f = write_file("kerf_window_syntax.ngc", "G0 X0 Y0\nM3\nG1 X10 F600\nG1 X20\n/G1 X30\nM5\n");
  std::unique_ptr<ProgramStream> s;
  std::string error;
  ProgramStreamOptions o;
  o.part_bytes = 16;
  EXPECT_FALSE(open_program_stream(f, InterpSettings{}, MachineState{}, o, s, error));
  EXPECT_EQ(error, f + ":5: block delete (/) is not supported");
  EXPECT_FALSE(open_program_stream(f + ".missing", InterpSettings{}, MachineState{}, o, s, error));
  EXPECT_EQ(error.rfind(f + ".missing: ", 0), 0u) << error;
}

// What the interpreter refuses comes when the stream reaches it: the paths
// before it are given first (the file is not read whole before the first).
TEST(ProgramWindow, AnInterpreterErrorComesAfterThePathsBeforeIt) {
  std::string text = "G0 X0 Y0\nM3\nG1 X10 F600\nG1 X10 Y10\nM5\nG0 X20 Y0\nM3\nG1 X30\nM5\n";
  for (int k = 0; k < 200; ++k) text += "G0 X" + std::to_string(k) + " Y1\n";
  text += "G41\nM2\n";
  const std::string f = write_file("kerf_window_interp_error.ngc", text);
  const Reading p = read(f, InterpSettings{}, MachineState{}, false, 64);
  ASSERT_TRUE(p.opened) << p.error;
  EXPECT_TRUE(p.window);
  EXPECT_EQ(p.d.paths, 2u);
  EXPECT_EQ(p.d.tail, "ERROR " + f + ":" + std::to_string(210) +
                          ": G41: cutter compensation is not supported (kerf compensation does not exist yet)");
  expect_same(f, InterpSettings{}, MachineState{}, 64);
}

TEST(ProgramWindow, NoCutMovesIsFoundAtTheEnd) {
  const std::string f = write_file("kerf_window_no_cut.ngc", "G0 X1 Y1\nM3\nG0 X2\nG4 P1\nM5\nM2\n");
  const Reading p = read(f, InterpSettings{}, MachineState{}, false, 8);
  ASSERT_TRUE(p.opened) << p.error;
  EXPECT_EQ(p.d.tail, "ERROR " + f + ": no cut moves (G1/G2/G3 with the torch on)");
  expect_same(f, InterpSettings{}, MachineState{}, 8);
}

// dry_run() is the scan's: the torch words up to the program's end.
TEST(ProgramWindow, DryRunIsKnownBeforeTheFirstItem) {
  struct Case {
    const char* text;
    bool dry;
    bool window;
  } cases[] = {
      {"G0 X0 Y0\nG1 X10 F600\nG1 Y10\nM2\n", true, true},
      {"G0 X0 Y0\nG1 X10 F600\nG1 Y10\nM3\n", false, true},          // a torch word after the cut still counts
      {"G0 X0 Y0\nG1 X10 F600\nG1 Y10\nM2\nM3\n", true, true},       // after the end: never runs
      {"G0 X0 Y0\nG1 X10 F600\nG1 Y10\nM30 M3\n", false, true},      // on the end's line: runs before it
      {"G0 X0 Y0\nM62 P0\nG1 X10 F600\nG1 Y10\nM2\n", false, true},  // the torch output
      {"G0 X0 Y0\nM62 P1\nG1 X10 F600\nG1 Y10\nM2\n", true, true},   // another output
      {"#1=0\nG0 X0 Y0\nM62 P#1\nG1 X10 F600\nG1 Y10\nM2\n", false, false},  // computed: read whole
      {"#1=3\nG0 X#1 Y0\nM3\nG1 X[#1*2] F600\nG1 Y10\nM2\n", false, true},    // parameters stream
      {"o1 repeat [2]\nG0 X0 Y0\nM3\nG1 X10 F600\nM5\no1 endrepeat\nM2\n", false, false},  // O-words: whole
  };
  InterpSettings s = kerf_test::interp_case_settings();  // the torch on output 0
  int k = 0;
  for (const Case& c : cases) {
    const std::string f = write_file("kerf_window_dry_" + std::to_string(k++) + ".ngc", c.text);
    std::unique_ptr<ProgramStream> stream;
    std::string error;
    ASSERT_TRUE(open_program_stream(f, s, MachineState{}, stream, error)) << error;
    EXPECT_EQ(stream->dry_run(), c.dry) << c.text;
    EXPECT_EQ(dynamic_cast<WindowProgramStream*>(stream.get()) != nullptr, c.window) << c.text;
    expect_same(f, s, MachineState{}, 4);
  }
}

// Line ends decided for the whole file, as read_gcode decides them: an LF
// anywhere makes the CRs before it part of a line; a file without one ends
// its lines at CR.
TEST(ProgramWindow, LineEndsAreTheWholeFilesInEveryPart) {
  const std::string cr = "G0 X0 Y0\rM3\rG1 X10 F600\rG1 Y10\rM5\rG0 X20\rM3\rG1 X30\rM5\r";
  const std::string cases[] = {cr, cr + "G1 X40\n", "G0 X0 Y0\r\nM3\r\nG1 X10 F600\r\nG1 Y10\r\n",
                               "G0 X0 Y0\nM3\nG1 X10 F600\nG1 Y10", std::string(70000, ' ') + "\nG1 X1 F1\n"};
  int k = 0;
  for (const std::string& text : cases) {
    const std::string f = write_file("kerf_window_ends_" + std::to_string(k++) + ".ngc", text);
    for (const std::size_t part : {std::size_t{1}, std::size_t{5}, std::size_t{64}})
      expect_same(f, InterpSettings{}, MachineState{}, part);
  }
}

// A named pipe cannot be read twice (the scan, then the window): it is read whole.
TEST(ProgramWindow, APipeIsReadWhole) {
  const std::string text = "G0 X0 Y0\nM3\nG1 X10 F600\nG1 Y10\nM5\nM2\n";
  const std::string plain = write_file("kerf_window_plain.ngc", text);
  const std::string fifo = ::testing::TempDir() + "kerf_window_fifo.ngc";
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo, std::ios::binary) << text; });
  const Reading p = read(fifo, InterpSettings{}, MachineState{}, false, 64);
  writer.join();
  std::remove(fifo.c_str());
  ASSERT_TRUE(p.opened) << p.error;
  EXPECT_FALSE(p.window);
  const Reading w = read(plain, InterpSettings{}, MachineState{}, false, 64);
  EXPECT_TRUE(w.window);
  EXPECT_EQ(p.d.items, w.d.items);
  EXPECT_EQ(p.d.paths, 1u);
}

}  // namespace

namespace {

// Random programs of the constructs that shape paths (rapids, feeds, arcs,
// Z changes with the torch on and off, the torch, dwells, pauses, outputs,
// feed %, tolerances, comments, parameters), read both ways with and without
// a z axis, in parts of 1 and 7 bytes: the same items.
std::string random_program(unsigned seed) {
  std::uint64_t s = seed * 6364136223846793005ull + 1442695040888963407ull;
  auto next = [&](int n) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<int>((s >> 33) % static_cast<std::uint64_t>(n));
  };
  std::string t = "G21 G90\n";
  double x = 0, y = 0;
  char line[160];
  for (int k = 0; k < 60; ++k) {
    const double nx = next(200) / 10.0, ny = next(200) / 10.0, z = next(3) * 1.5;
    switch (next(14)) {
      case 0: std::snprintf(line, sizeof line, "G0 X%.1f Y%.1f\n", nx, ny), x = nx, y = ny; break;
      case 1: std::snprintf(line, sizeof line, "M3\n"); break;
      case 2: std::snprintf(line, sizeof line, "M5\n"); break;
      case 3: std::snprintf(line, sizeof line, "G1 Z%.1f F300\n", z); break;
      case 4: std::snprintf(line, sizeof line, "G0 X%.1f Y%.1f Z%.1f\n", nx, ny, z), x = nx, y = ny; break;
      case 5: std::snprintf(line, sizeof line, "G4 P0.%d\n", next(9)); break;
      case 6: std::snprintf(line, sizeof line, "M%d\n", next(2) == 0 ? 0 : 1); break;
      case 7: std::snprintf(line, sizeof line, "M6%d P%d\n", 2 + next(4), next(3)); break;
      case 8: std::snprintf(line, sizeof line, "M67 E3 Q%d\n", 10 + next(90)); break;
      case 9: std::snprintf(line, sizeof line, "G64 P0.0%d (tol)\n", 1 + next(9)); break;
      case 10: {  // an arc about a centre one to three mm away, to a point on its circle
        const double r = 1 + next(3), a = next(360) * 3.14159265358979 / 180;
        const double cx = x - r * std::cos(a), cy = y - r * std::sin(a), b = a + (1 + next(300)) * 0.01;
        const double ex = cx + r * std::cos(b), ey = cy + r * std::sin(b);
        std::snprintf(line, sizeof line, "G%d X%.6f Y%.6f I%.6f J%.6f F%d\n", next(2) == 0 ? 2 : 3, ex, ey, cx - x,
                      cy - y, 500 + next(5) * 100);
        x = ex, y = ey;
        break;
      }
      case 11: std::snprintf(line, sizeof line, "#1 = %.1f\nG1 X[#1 + 1] Y%.1f Z%.1f\n", nx, ny, z), x = nx + 1, y = ny; break;
      default: std::snprintf(line, sizeof line, "G1 X%.1f Y%.1f F%d ; cut\n", nx, ny, 600 + next(3) * 300), x = nx, y = ny;
    }
    t += line;
  }
  if (next(2) == 0) t += "M2\n";
  return t;
}

TEST(ProgramWindow, RandomProgramsGiveWhatTheWholeReadingGives) {
  std::size_t cut = 0, paths = 0, actions = 0;
  for (unsigned seed = 0; seed < 120; ++seed) {
    const std::string f = write_file("kerf_window_random.ngc", random_program(seed));
    InterpSettings s = kerf_test::interp_case_settings();
    const Reading r = read(f, s, MachineState{}, false, 64);
    cut += r.d.ok;
    paths += r.d.paths;
    actions += r.d.actions;
    for (const bool z : {false, true}) {
      s.z_axis = z;
      expect_same(f, s, MachineState{}, 1);
      expect_same(f, s, MachineState{}, 7);
    }
    if (::testing::Test::HasFailure()) {
      ADD_FAILURE() << "seed " << seed << ":\n" << random_program(seed);
      break;
    }
  }
  std::printf("120 programs: %zu cut, %zu paths, %zu actions\n", cut, paths, actions);
  EXPECT_GE(cut, 60u) << "the programs are mostly correct";
  EXPECT_GE(paths, 400u);
}

}  // namespace
