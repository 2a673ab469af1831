// kerf weld streamed part by part (weld/weld.hpp: weld_stream) against the
// whole-file weld (weld_gcode, kept as this oracle): the same bytes on every
// corpus file while the windows hold whole polylines, valid output within tol
// where a window cuts one, errors at the same FILE:LINE.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../gcode/weld_checker.hpp"
#include "job/gcode_reader.hpp"
#include "weld/weld.hpp"
#include "weld_pipe.hpp"

namespace {

namespace fs = std::filesystem;
using kerf::weld::StreamEnd;
using kerf::weld::StreamOptions;
using kerf::weld::WeldOptions;
using kerf::weld::WeldStats;

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// Every G-code file of tests/data/gcode, and of $KERF_EXTRA_GCODE_DIR when set.
std::vector<fs::path> corpus() {
  std::vector<fs::path> files;
  std::vector<fs::path> dirs{fs::path(KERF_TEST_DATA_DIR) / "gcode"};
  if (const char* extra = std::getenv("KERF_EXTRA_GCODE_DIR")) dirs.emplace_back(extra);
  for (const fs::path& d : dirs)
    for (const auto& e : fs::directory_iterator(d))
      if (kerf::job::is_gcode_path(e.path().string())) files.push_back(e.path());
  return files;
}

struct Streamed {
  StreamEnd end = StreamEnd::ok;
  std::string out, error;
  WeldStats stats;
};

// Streams text as weld_file does for a file: decimals from a first pass.
Streamed stream(const std::string& text, WeldOptions o, const StreamOptions& so, bool scan = true) {
  Streamed s;
  std::string copy = text;  // fmemopen wants a writable buffer for "r" on some libcs
  std::FILE* f = fmemopen(copy.data(), copy.size(), "rb");
  if (copy.empty()) f = std::tmpfile();
  if (scan) {
    kerf::weld::GcodeScan sc;
    if (!kerf::weld::scan_gcode(f, "job.nc", so.chunk_bytes, sc, s.error)) {
      std::fclose(f);
      s.end = StreamEnd::bad_input;
      return s;
    }
    if (o.decimals < 0) o.decimals = std::max<int>(3, static_cast<int>(sc.decimals));
    std::rewind(f);
  }
  s.end = kerf::weld::weld_stream(
      f, "job.nc", [&](const std::string& t) { return s.out += t, true; }, o, so, s.stats, s.error);
  std::fclose(f);
  return s;
}

TEST(WeldStream, SameBytesAsTheWholeFileOnTheCorpus) {
  for (const fs::path& p : corpus()) {
    const std::string text = slurp(p);
    const kerf::job::GcodeFile g = kerf::job::parse_gcode(text, "job.nc");
    ASSERT_TRUE(g.ok) << p;
    for (const int threads : {1, 2}) {
      WeldOptions o;
      o.threads = threads;
      std::string whole, error;
      WeldStats ws;
      ASSERT_TRUE(kerf::weld::weld_gcode(g, o, whole, ws, error)) << p << ": " << error;
      // Parts of 4 KiB: most polylines are read twice; the window holds them all.
      for (const std::size_t chunk : {std::size_t{4096}}) {
        StreamOptions so;
        so.chunk_bytes = chunk;
        so.window_lines = std::size_t{1} << 30;
        const Streamed s = stream(text, o, so);
        ASSERT_EQ(s.end, StreamEnd::ok) << p << ": " << s.error;
        EXPECT_TRUE(s.out == whole) << p << " (parts of " << chunk << " bytes, " << threads
                                    << " threads): not the whole-file weld's bytes";
        EXPECT_EQ(s.stats.input_moves, ws.input_moves) << p;
        EXPECT_EQ(s.stats.output_moves, ws.output_moves) << p;
        EXPECT_EQ(s.stats.arcs, ws.arcs) << p;
        EXPECT_EQ(s.stats.kept_pieces, ws.kept_pieces) << p;
        EXPECT_EQ(s.stats.forced_commits, 0u) << p;
        EXPECT_EQ(s.stats.lines, g.blocks.size()) << p;
      }
    }
  }
}

TEST(WeldStream, ScanFindsTheWholeFilesDecimals) {
  for (const fs::path& p : corpus()) {
    const std::string text = slurp(p);
    std::string copy = text;
    std::FILE* f = fmemopen(copy.data(), copy.size(), "rb");
    kerf::weld::GcodeScan sc;
    std::string error;
    ASSERT_TRUE(kerf::weld::scan_gcode(f, "job.nc", 4096, sc, error)) << error;
    std::fclose(f);
    const kerf::job::GcodeFile g = kerf::job::parse_gcode(text, "job.nc");
    EXPECT_EQ(sc.decimals, g.decimals) << p;
    EXPECT_EQ(sc.lines, g.blocks.size()) << p;
  }
}

// A window of 40 lines cuts the long polylines: counted, and the output is
// still within tol of the input (the independent referee).
TEST(WeldStream, ForcedCommitsAreCountedAndStayWithinTol) {
  for (const char* name : {"cncjs_jsdc-laser.gcode", "cncjs_tball-engrave.gcode"}) {
    const std::string text = slurp(fs::path(KERF_TEST_DATA_DIR) / "gcode" / name);
    StreamOptions so;
    so.chunk_bytes = 2048;
    so.window_lines = 40;
    const Streamed s = stream(text, WeldOptions{}, so);
    ASSERT_EQ(s.end, StreamEnd::ok) << name << ": " << s.error;
    EXPECT_GT(s.stats.forced_commits, 0u) << name;
    const kerf_test::WeldCheck c = kerf_test::check_weld(text, s.out, 0.025);
    EXPECT_TRUE(c.ok) << name << ": " << c.why;
    EXPECT_LE(c.max_deviation, 0.025) << name;
  }
}

// A bad line far into the file: the same FILE:LINE as the whole-file read.
TEST(WeldStream, AnErrorInALaterPartHasItsLineNumber) {
  std::string text = "G21 G90\n";
  for (std::uint64_t k = 0; k < 200; ++k) kerf_test::append_shape(text, k);
  text += "G1 X1 Y2 Q\n";
  const kerf::job::GcodeFile g = kerf::job::parse_gcode(text, "job.nc");
  ASSERT_FALSE(g.ok);
  StreamOptions so;
  so.chunk_bytes = 1000;
  for (const bool scan : {true, false}) {
    const Streamed s = stream(text, WeldOptions{}, so, scan);
    EXPECT_EQ(s.end, StreamEnd::bad_input);
    EXPECT_EQ(s.error, kerf::job::describe_error(g));
  }
}

// Without a first pass (stdin), the decimals are the most seen so far: the
// same bytes when the file uses the same decimals throughout.
TEST(WeldStream, StdinWithoutAFirstPassGivesTheSameBytes) {
  std::string text;
  for (std::uint64_t k = 0; k < 300; ++k) kerf_test::append_shape(text, k);
  const kerf::job::GcodeFile g = kerf::job::parse_gcode(text, "job.nc");
  std::string whole, error;
  WeldStats ws;
  ASSERT_TRUE(kerf::weld::weld_gcode(g, WeldOptions{}, whole, ws, error)) << error;
  StreamOptions so;
  so.chunk_bytes = 3000;
  const Streamed s = stream(text, WeldOptions{}, so, false);
  ASSERT_EQ(s.end, StreamEnd::ok) << s.error;
  EXPECT_TRUE(s.out == whole);
  EXPECT_EQ(ws.arcs, 600u);  // two a circle
}

// The kerf command on generated jobs of 1e5, 1e6 and 1e7 lines, piped
// through: its peak RSS at 1e7 is at most 1.2 times that at 1e5 plus 16 MB.
TEST(WeldScale, PeakMemoryDoesNotGrowWithTheFile) {
  const std::uint64_t sizes[] = {100000, 1000000, 10000000};
  long smallest = 0;
  for (const std::uint64_t n : sizes) {
    const bool first = n == sizes[0];
    const kerf_test::PipeRun r = kerf_test::weld_pipe(KERF_BIN, n, 2, first);
    ASSERT_TRUE(r.ok) << n << " lines: " << r.err;
    const std::uint64_t shapes = (n + kerf_test::kShapeLines - 1) / kerf_test::kShapeLines;
    EXPECT_NE(r.err.find("input moves: " + std::to_string((kerf_test::kShapeLines - 3) * shapes) + "\n"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("arcs: " + std::to_string(2 * shapes) + "\n"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("forced commits: 0\n"), std::string::npos) << r.err;
    std::printf("kerf weld, %llu lines: peak RSS %ld kB, %.2f s\n", static_cast<unsigned long long>(r.lines),
                r.max_rss_kb, r.seconds);
    if (first) {
      smallest = r.max_rss_kb;
      std::string text;  // the same job, welded whole in this process
      for (std::uint64_t k = 0; k < shapes; ++k) kerf_test::append_shape(text, k);
      const kerf::job::GcodeFile g = kerf::job::parse_gcode(text, "job.nc");
      std::string whole, error;
      WeldStats ws;
      ASSERT_TRUE(kerf::weld::weld_gcode(g, WeldOptions{}, whole, ws, error)) << error;
      EXPECT_TRUE(r.out == whole) << "the streamed output is not the whole-file weld's";
    } else {
      EXPECT_LE(r.max_rss_kb, smallest * 6 / 5 + 16 * 1024) << n << " lines";
    }
  }
}

}  // namespace
