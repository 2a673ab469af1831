// `kerf weld` on several threads writes what the sequential weld writes,
// byte for byte, with the same stats, progress and first error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "weld/weld.hpp"
#include "job/gcode_reader.hpp"

namespace {

using kerf::weld::WeldOptions;
using kerf::weld::WeldStats;

struct Welded {
  bool ok = false;
  std::string text;
  std::string error;
  WeldStats stats;
  std::vector<std::size_t> progress;
  bool progress_on_caller = true;  // every progress call came from the calling thread
};

Welded weld(const kerf::job::GcodeFile& g, WeldOptions o, int threads) {
  Welded w;
  o.threads = threads;
  const std::thread::id caller = std::this_thread::get_id();
  o.progress = [&](std::size_t line) {
    w.progress.push_back(line);
    if (std::this_thread::get_id() != caller) w.progress_on_caller = false;
  };
  w.ok = kerf::weld::weld_gcode(g, o, w.text, w.stats, w.error);
  return w;
}

void expect_same(const Welded& one, const Welded& many, const std::string& what) {
  EXPECT_EQ(one.ok, many.ok) << what;
  EXPECT_EQ(one.error, many.error) << what;
  EXPECT_TRUE(one.text == many.text) << what << ": the output differs";  // not printed: megabytes
  EXPECT_EQ(one.stats.input_moves, many.stats.input_moves) << what;
  EXPECT_EQ(one.stats.output_moves, many.stats.output_moves) << what;
  EXPECT_EQ(one.stats.arcs, many.stats.arcs) << what;
  EXPECT_EQ(one.stats.polylines, many.stats.polylines) << what;
  EXPECT_EQ(one.stats.kept_pieces, many.stats.kept_pieces) << what;
  EXPECT_EQ(one.stats.max_deviation_mm, many.stats.max_deviation_mm) << what;  // a max: exactly
  EXPECT_EQ(one.stats.decimals, many.stats.decimals) << what;
  EXPECT_TRUE(one.progress == many.progress) << what << ": the progress calls differ";
  EXPECT_TRUE(many.progress_on_caller) << what << ": progress called from a worker thread";
}

std::vector<std::filesystem::path> corpus_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(KERF_TEST_DATA_DIR) + "/gcode"))
    if (e.path().extension() == ".gcode") files.push_back(e.path());
  return files;
}

TEST(WeldThreads, CorpusIsTheSameOnOneAndFourThreads) {
  const std::vector<std::filesystem::path> files = corpus_files();
  ASSERT_FALSE(files.empty());
  std::size_t arcs = 0;
  for (const std::filesystem::path& file : files) {
    const kerf::job::GcodeFile g = kerf::job::read_gcode(file.string());
    ASSERT_TRUE(g.ok) << kerf::job::describe_error(g);
    for (const char* criterion : {"band", "vertex"}) {
      WeldOptions o;
      o.tol_mm = 0.025;
      o.criterion = *kerf::job::parse_criterion(criterion);
      const Welded one = weld(g, o, 1);
      ASSERT_TRUE(one.ok) << one.error;
      arcs += one.stats.arcs;
      expect_same(one, weld(g, o, 4), file.filename().string() + " " + criterion);
    }
  }
  EXPECT_GT(arcs, 0u);  // the comparison is of welded files
}

// Coarser decimals than the file's leave the machine off the input's points
// after some polylines: the plan of the next one, made from its own first
// point, is made again from where the machine is.
TEST(WeldThreads, CoarseDecimalsAreTheSame) {
  for (const char* name : {"cncjs_jsdc-laser.gcode", "cncjs_tball-engrave.gcode"}) {
    const kerf::job::GcodeFile g = kerf::job::read_gcode(std::string(KERF_TEST_DATA_DIR) + "/gcode/" + name);
    ASSERT_TRUE(g.ok) << kerf::job::describe_error(g);
    WeldOptions o;
    o.tol_mm = 0.025;
    o.decimals = 2;
    const Welded one = weld(g, o, 1);
    ASSERT_TRUE(one.ok) << one.error;
    expect_same(one, weld(g, o, 4), std::string(name) + " --decimals 2");
  }
}

// A spiral of G1 lines, a new polyline at each F word (every 50 lines: parts
// large enough for the pool, PlanPool::kPooledPoints); with
// one decimal each polyline's last arc ends off its input point, so the next
// one starts from there (its I/J differ from a plan made from its own point).
TEST(WeldThreads, PlansFromWhereTheMachineIs) {
  std::string text = "G21 G90\nG0 X10 Y0\nM03\n";
  for (int k = 1; k <= 2000; ++k) {
    const double t = k * 0.025, r = 10 + 0.3 * t;
    char buf[96];
    std::snprintf(buf, sizeof buf, "G1 X%.3f Y%.3f", r * std::cos(t), r * std::sin(t));
    text += buf;
    if (k % 50 == 0) text += k % 100 == 0 ? " F100" : " F200";
    text += '\n';
  }
  text += "M05\n";
  const kerf::job::GcodeFile g = kerf::job::parse_gcode(text, "spiral.nc");
  ASSERT_TRUE(g.ok) << kerf::job::describe_error(g);
  ASSERT_GE(g.polylines.size(), 40u);
  WeldOptions o;
  o.tol_mm = 0.5;
  o.decimals = 1;
  o.jitter = 0;  // all 50 points fitted: each polyline goes through the pool
  const Welded one = weld(g, o, 1);
  ASSERT_TRUE(one.ok) << one.error;
  EXPECT_GE(one.stats.arcs, 40u);  // at least one per polyline: each ends off its point
  expect_same(one, weld(g, o, 4), "spiral --decimals 1");
}

// Every polyline fails (no tol the fitters take): the error names the first
// in file order, whichever thread failed first.
TEST(WeldThreads, FirstErrorInFileOrder) {
  const kerf::job::GcodeFile g =
      kerf::job::read_gcode(std::string(KERF_TEST_DATA_DIR) + "/gcode/cncjs_tball-engrave.gcode");
  ASSERT_TRUE(g.ok) << kerf::job::describe_error(g);
  WeldOptions o;
  o.tol_mm = std::nan("");
  const Welded one = weld(g, o, 1);
  ASSERT_FALSE(one.ok);
  // Built with += : armhf GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&.
  std::string first_line = ":";
  first_line += std::to_string(g.blocks[g.polylines.front().first_block].line);
  first_line += ": ";
  EXPECT_NE(one.error.find(first_line), std::string::npos) << one.error;
  for (int run = 0; run < 5; ++run) {
    std::string what = "NaN tol, run ";
    what += std::to_string(run);
    expect_same(one, weld(g, o, 4), what);
  }
}

TEST(WeldThreads, ThreadCount) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  EXPECT_EQ(kerf::weld::weld_threads(0), cores);
  EXPECT_EQ(kerf::weld::weld_threads(1), 1u);
  EXPECT_EQ(kerf::weld::weld_threads(1000), cores);
}

}  // namespace
