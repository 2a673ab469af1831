// kerf run's streamed job (control/streamed_job.hpp): the producer reads and
// fits the file path by path while the controller cuts. Its source gives the
// same path heads, z moves, segments (bit for bit) and actions as the whole
// job on the corpus's QtPlasmaC programs, with a z axis and as a dry run; on
// the board it cuts the same segments in the same order; a resume from its
// journal cuts each segment once; a bad path far into the file is a fault
// with the progress kept.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "control/program_job.hpp"
#include "job/fit_job.hpp"
#include "job/gcode_reader.hpp"
#include "control/streamed_job.hpp"
#include "simulated/sim_machine.hpp"
#include "simulated/sim_plant.hpp"
#include "fake_gpio.hpp"

namespace kerf::test {
namespace {

namespace fs = std::filesystem;

std::string temp_dir() {
  const std::string dir = fs::temp_directory_path() / ("kerf_streamed_job_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

control::StreamedJobSetup setup(bool z_axis, bool dry_run) {
  control::StreamedJobSetup s;
  s.criterion = job::Criterion::band;
  s.tol = 0.02;
  s.feed_mm_s = 50.0;
  s.max_feed_mm_s = 200.0;
  s.rules = config::CutRules{};
  s.rules->overcut = 1.0;
  s.rules->arc_radius = 3.0;
  s.rules->arc_feed = 70;
  s.torch_off = dry_run;
  s.outputs_off = dry_run;
  s.interp.z_axis = z_axis;
  return s;
}

// The whole job as kerf run built it before it streamed.
control::FittedJob whole(const std::string& file, const control::StreamedJobSetup& s) {
  control::FittedJob f;
  if (job::is_gcode_path(file)) {
    job::GcodeProgram prog;
    std::string error;
    EXPECT_TRUE(job::read_gcode_program(file, s.interp, s.state, prog, error)) << error;
    EXPECT_EQ(control::fit_program_or_say(prog, s.criterion, s.tol, s.feed_mm_s, s.max_feed_mm_s, f, s.numeric,
                                          &*s.rules),
              0);
  } else {
    io::PointFile in;
    EXPECT_TRUE(job::read_job(file, s.criterion, in));
    EXPECT_EQ(control::fit_paths_or_say(in, s.criterion, s.tol, s.feed_mm_s, f, s.numeric, &*s.rules), 0);
  }
  if (s.torch_off) control::hold_outputs_off(f.job, s.outputs_off);
  return f;
}

std::string describe(const hal::SegmentCommand& c) {
  char t[200];
  std::snprintf(t, sizeof t, "%d %a %a %a %a %d %a %d %d %a", static_cast<int>(c.kind), c.end.x, c.end.y, c.centre.x,
                c.centre.y, c.dir, c.feed, c.torch, c.z_move, c.z);
  return t;
}

std::string describe(const control::JobAction& a) {
  char t[160];
  std::snprintf(t, sizeof t, "action %d before %zu line %zu index %d mode %d %a %d", static_cast<int>(a.kind),
                a.before_path, a.line, a.index, a.mode, a.value, a.sync);
  return t;
}

// Everything the controller reads of a source, in its order, as text (%a: bit for bit).
std::vector<std::string> drain(control::JobSource& src) {
  std::vector<std::string> out;
  std::size_t next_action = 0;
  const auto actions = [&](std::size_t upto) {  // the actions before path `upto` and before it
    for (const control::JobAction* a = src.action(next_action); a != nullptr && a->before_path <= upto;
         a = src.action(++next_action))
      out.push_back(describe(*a));
  };
  const auto wait = [] { std::this_thread::sleep_for(std::chrono::microseconds(100)); };
  src.locate(0);
  for (std::size_t p = 0;; ++p) {
    const control::PathHead* h = nullptr;
    while ((h = src.open(p)) == nullptr && p < src.path_count() && *src.error() == '\0') wait();
    actions(h == nullptr ? static_cast<std::size_t>(-1) : p);
    if (h == nullptr) break;
    char t[120];
    std::snprintf(t, sizeof t, "path %zu at %a %a torch %d pierce %a first %zu", p, h->start.x, h->start.y, h->torch,
                  h->pierce_delay_s, h->first_segment);
    out.push_back(t);
    for (const hal::SegmentCommand& c : *h->before) out.push_back("before " + describe(c));
    const hal::SegmentCommand* c = nullptr;
    for (std::size_t i = 0;; ++i) {
      control::Pull pull;
      while ((pull = src.segment(i, c)) == control::Pull::later) wait();
      if (pull != control::Pull::ready) break;
      out.push_back(describe(*c));
    }
    for (const hal::SegmentCommand& a : *h->after) out.push_back("after " + describe(a));
  }
  out.push_back(std::string("error ") + src.error());
  return out;
}

std::vector<std::string> corpus() {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(KERF_GCODE_DIR))
    if (e.path().filename().string().rfind("linuxcnc_plasmac_", 0) == 0) files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(StreamedJob, TheSourceGivesTheWholeJobsCommandsOnTheCorpus) {
  const std::vector<std::string> files = corpus();
  ASSERT_GE(files.size(), 10u);
  std::size_t segments = 0, actions = 0, moves = 0, refusals = 0;
  for (const std::string& file : files)
    for (const auto& [z, dry] : {std::pair{false, false}, std::pair{true, false}, std::pair{true, true}}) {
      const control::StreamedJobSetup s = setup(z, dry);
      job::GcodeProgram prog;
      std::string why;
      if (!job::read_gcode_program(file, s.interp, s.state, prog, why)) {  // refused whole: refused streamed, the same words
        control::StreamedJob refused;
        std::string error;
        if (refused.open(file, s, error) == 0) {
          EXPECT_EQ(refused.prime(error), 2) << file;
        }
        EXPECT_EQ(error, why);
        ++refusals;
        continue;
      }
      const control::FittedJob f = whole(file, s);
      control::WholeJobSource oracle(f.job);
      const std::vector<std::string> want = drain(oracle);
      control::StreamedJob streamed;
      std::string error;
      ASSERT_EQ(streamed.open(file, s, error), 0) << error;
      ASSERT_EQ(streamed.prime(error), 0) << error;
      const std::vector<std::string> got = drain(streamed.source());
      ASSERT_EQ(got, want) << file << (z ? " z axis" : "") << (dry ? " dry run" : "");
      const control::StreamTotals t = streamed.totals();
      EXPECT_TRUE(t.ended);
      EXPECT_EQ(t.paths, f.job.paths.size()) << file;
      EXPECT_EQ(t.segments, f.job.segment_count()) << file;
      EXPECT_EQ(t.lines_for_arcs, f.lines_for_arcs) << file;
      EXPECT_EQ(t.cut_rules.size(), f.cut_rules.size()) << file;
      EXPECT_EQ(streamed.source().segment_count(), f.job.segment_count());
      segments += t.segments;
      actions += f.job.actions.size();
      for (const control::CutPath& p : f.job.paths) moves += p.before.size() + p.after.size();
    }
  std::printf("%zu files x 3 setups: %zu segments, %zu actions, %zu z/travel moves, the same bit for bit; %zu refused alike\n",
              files.size(), segments, actions, moves, refusals);
  EXPECT_GT(actions, 0u);
  EXPECT_GT(moves, 0u);
}

// Point files (paths separated by blank lines), read path by path: the whole job's segments.
TEST(StreamedJob, PointFilesStreamTheWholeJobsSegments) {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(KERF_EXAMPLES_DIR))
    if (e.path().extension() == ".txt") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 2u);
  std::size_t paths = 0;
  for (const std::string& file : files) {
    const control::StreamedJobSetup s = setup(false, false);
    const control::FittedJob f = whole(file, s);
    control::WholeJobSource oracle(f.job);
    control::StreamedJob streamed;
    std::string error;
    ASSERT_EQ(streamed.open(file, s, error), 0) << error;
    ASSERT_EQ(streamed.prime(error), 0) << error;
    EXPECT_EQ(drain(streamed.source()), drain(oracle)) << file;
    paths += f.job.paths.size();
  }
  EXPECT_GT(paths, files.size()) << "some file has many paths";
}

simulated::SimMachineResult run(control::JobSource& source, control::MemoryOutputs& outputs,
                                control::Journal* journal = nullptr, const control::ResumePoint& from = {},
                                std::vector<simulated::BoardFault> faults = {}) {
  FakeGpio gpio;
  control::ControllerConfig cfg;
  cfg.pierce_delay_s = 0.02;
  cfg.rapid_feed_mm_s = 400.0;
  cfg.outputs = &outputs;
  simulated::SimMachineConfig m;
  m.faults = std::move(faults);
  m.trace_sink = [](const sim::TraceSample&) {};
  std::string error;
  std::unique_ptr<simulated::SimPlant> plant = simulated::make_modbus_plant(m, cfg.link_watchdog_s, error);
  EXPECT_TRUE(plant != nullptr) << error;
  if (!plant) return {};
  return simulated::run_sim_machine(source, cfg, m, *plant, gpio, journal, from);
}

// A program of `paths` zigzags of 48 points (each point a corner: about a
// segment a point), an output on after each; `tail` ends it. Path p starts
// at line 2 + 52 p, the tail at line 2 + 52 paths.
std::string zigzags_file(const std::string& name, int paths, const std::string& tail = "") {
  const std::string path = temp_dir() + "/" + name;
  std::ofstream f(path);
  f << "G21 G90\n";
  for (int p = 0; p < paths; ++p) {
    const double x0 = 12.0 * (p % 8), y0 = 4.0 * (p / 8);
    f << "G0 X" << x0 << " Y" << y0 << "\nM3 S1\n";
    for (int k = 1; k <= 48; ++k) f << "G1 X" << x0 + 0.2 * k << " Y" << y0 + (k % 2) * 0.3 << " F3000\n";
    f << "M5\nM64 P" << (p % 2) << "\n";
  }
  f << tail << "M2\n";
  return path;
}

TEST(StreamedJob, CutsTheWholeJobsSegmentsOnTheBoard) {
  const std::string file = fs::path(KERF_GCODE_DIR) / "linuxcnc_plasmac_metric_wrench.ngc";
  const control::StreamedJobSetup s = setup(false, false);
  const control::FittedJob f = whole(file, s);
  control::WholeJobSource oracle(f.job);
  control::MemoryOutputs out_whole, out_streamed;
  const simulated::SimMachineResult a = run(oracle, out_whole);
  control::StreamedJob streamed;
  std::string error;
  ASSERT_EQ(streamed.open(file, s, error), 0) << error;
  ASSERT_EQ(streamed.prime(error), 0) << error;
  const simulated::SimMachineResult b = run(streamed.source(), out_streamed);
  ASSERT_EQ(a.run.state, control::State::done) << a.run.reason;
  ASSERT_EQ(b.run.state, control::State::done) << b.run.reason;
  EXPECT_EQ(b.executed, a.executed);
  EXPECT_EQ(b.run.completed_this_run, a.run.completed_this_run);
  EXPECT_EQ(b.run.pierces, a.run.pierces);
  EXPECT_EQ(b.run.actions.size(), a.run.actions.size());
  EXPECT_EQ(out_streamed.digital, out_whole.digital);
  EXPECT_EQ(out_streamed.analog, out_whole.analog);
  EXPECT_EQ(b.board.position, a.board.position);
  // The trace recorder's piece of a recent segment.
  std::size_t path = 99;
  const fit::Piece<double>* last = streamed.piece(f.job.segment_count() - 1, &path);
  ASSERT_NE(last, nullptr);
  EXPECT_EQ(path, f.job.paths.size() - 1);
  EXPECT_EQ(last->last, f.pieces.back().last);
  EXPECT_EQ(streamed.piece(f.job.segment_count(), nullptr), nullptr);
}

// The first segment runs on the board before the producer has read the file
// to its end (the ring holds fewer items than the job has).
TEST(StreamedJob, TheFirstSegmentRunsBeforeTheFileIsReadToItsEnd) {
  const std::string file = zigzags_file("first.ngc", 40);
  control::StreamedJob streamed;
  std::string error;
  ASSERT_EQ(streamed.open(file, setup(false, false), error), 0) << error;
  ASSERT_EQ(streamed.prime(error), 0) << error;
  FakeGpio gpio;
  control::ControllerConfig cfg;
  cfg.pierce_delay_s = 0.02;
  simulated::SimMachineConfig m;
  bool seen = false;
  control::StreamTotals at_first;
  m.trace_sink = [&](const sim::TraceSample& t) {
    if (t.seq == 0 || seen) return;
    seen = true;
    at_first = streamed.totals();
  };
  std::unique_ptr<simulated::SimPlant> plant = simulated::make_modbus_plant(m, cfg.link_watchdog_s, error);
  ASSERT_TRUE(plant != nullptr) << error;
  const simulated::SimMachineResult r = simulated::run_sim_machine(streamed.source(), cfg, m, *plant, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, control::State::done) << r.run.reason;
  const control::StreamTotals t = streamed.totals();
  ASSERT_TRUE(seen);
  std::printf("the first segment ran with %zu of %zu paths (%zu of %zu segments) handed on\n", at_first.paths, t.paths,
              at_first.segments, t.segments);
  EXPECT_FALSE(at_first.ended) << "the file was read to its end before the first segment ran";
  EXPECT_LT(at_first.segments, t.segments);
  EXPECT_EQ(r.run.completed_this_run, t.segments);
}

// Stopped by a drive fault after more segments than the source keeps, then
// resumed from the journal by a new StreamedJob: each segment once; the
// outputs before the resumed path are set again. Another file is refused.
TEST(StreamedJob, AResumeFromTheJournalCutsEachSegmentOnce) {
  const std::string file = zigzags_file("resume.ngc", 40);
  const control::StreamedJobSetup s = setup(false, false);
  const std::string journal_path = temp_dir() + "/journal";
  std::string error;
  std::size_t first_run = 0;
  control::JobId id{};
  {
    control::StreamedJob streamed;
    ASSERT_EQ(streamed.open(file, s, error), 0) << error;
    ASSERT_EQ(streamed.prime(error), 0) << error;
    id = streamed.id();
    std::unique_ptr<control::Journal> journal = control::Journal::create(journal_path, id, error);
    ASSERT_TRUE(journal) << error;
    control::MemoryOutputs out;
    const simulated::SimMachineResult r =
        run(streamed.source(), out, journal.get(), {}, {{simulated::BoardFaultKind::drive_fault, 15.0, 0.0}});
    ASSERT_EQ(r.run.state, control::State::fault) << r.run.reason;
    first_run = r.executed.size();
  }
  const control::FittedJob f = whole(file, s);
  ASSERT_GT(first_run, control::StreamedJob::kHistory / 4);
  ASSERT_LT(first_run, f.job.segment_count());
  std::unique_ptr<control::Journal> again = control::Journal::resume(journal_path, id, error);
  ASSERT_TRUE(again) << error;
  control::StreamedJob streamed;
  ASSERT_EQ(streamed.open(file, s, error), 0) << error;
  ASSERT_EQ(streamed.prime(error), 0) << error;
  EXPECT_EQ(streamed.id().hash, id.hash);
  const control::ResumePoint rp = control::resume_point(streamed.source(), again->state());
  control::MemoryOutputs out;
  const simulated::SimMachineResult r2 = run(streamed.source(), out, again.get(), rp);
  ASSERT_EQ(r2.run.state, control::State::done) << r2.run.reason;
  EXPECT_EQ(again->state().executed_total, f.job.segment_count());
  EXPECT_EQ(again->state().duplicates, 0u);
  EXPECT_TRUE(again->state().finished);
  ASSERT_GE(out.digital.size(), 2u);  // M64 P0 and P1 set again before the first move
  EXPECT_EQ(out.digital[0].second, true);
  EXPECT_EQ(out.digital[1].second, true);
  // Another file or other settings: another id.
  control::StreamedJob other, finer;
  control::StreamedJobSetup s2 = s;
  s2.tol = 0.01;
  ASSERT_EQ(other.open(zigzags_file("other.ngc", 41), s, error), 0) << error;
  ASSERT_EQ(finer.open(file, s2, error), 0) << error;
  EXPECT_NE(other.id().hash, id.hash);
  EXPECT_NE(finer.id().hash, id.hash);
  again.reset();
  EXPECT_FALSE(control::Journal::resume(journal_path, other.id(), error));
}

// locate() of a segment behind the source's history, or in a path before the
// newest, reads and fits the file again from its start: the same segment.
TEST(StreamedJob, LocateBehindTheHistoryReadsTheFileAgain) {
  const std::string file = zigzags_file("rewind.ngc", 40);
  const control::StreamedJobSetup s = setup(false, false);
  const control::FittedJob f = whole(file, s);
  control::WholeJobSource oracle(f.job);
  control::StreamedJob streamed;
  std::string error;
  ASSERT_EQ(streamed.open(file, s, error), 0) << error;
  ASSERT_EQ(streamed.prime(error), 0) << error;
  control::JobSource& src = streamed.source();
  const std::size_t n = f.job.segment_count();
  ASSERT_GT(n, control::StreamedJob::kHistory + 200);
  const auto same = [&](std::size_t k) {
    const control::SegmentPlace want = oracle.locate(k);
    const control::SegmentPlace got = src.locate(k);
    EXPECT_EQ(got.path, want.path) << k;
    EXPECT_EQ(got.index, want.index) << k;
    EXPECT_EQ(describe(got.segment), describe(want.segment)) << k;
    EXPECT_EQ(got.start, want.start) << k;
    const control::PathHead* h = src.open(got.path);
    ASSERT_NE(h, nullptr) << k;
    EXPECT_EQ(h->first_segment, k - got.index) << k;
  };
  same(n - 10);  // forward, past the history's length
  same(n - 60);  // in the newest path's history: no second reading
  same(3);       // behind the history: read again
  same(200);     // forward again
  same(150);     // an older path: read again
  const hal::SegmentCommand* c = nullptr;
  EXPECT_EQ(src.segment(src.locate(150).index + 1, c), control::Pull::ready);
  EXPECT_EQ(describe(*c), describe(oracle.locate(151).segment));
}

// A path outside the soft limits far into the file: the job has started
// (prime does not wait for the file's end); the producer's error is a fault,
// torch off, the progress journaled, the message FILE:LINE.
TEST(StreamedJob, ABadPathFarIntoTheFileIsAFaultWithTheProgressKept) {
  const std::string file = zigzags_file("far.ngc", 40, "G0 X0 Y0\nM3 S1\nG1 X500 Y0 F3000\nG1 X500 Y5\nM5\n");
  control::StreamedJobSetup s = setup(false, false);
  motion::SoftLimits<double> limits;
  limits.on[0] = limits.on[1] = true;
  limits.max[0] = limits.max[1] = 200;
  limits.min[0] = limits.min[1] = -1;
  s.limits = limits;
  control::StreamedJob streamed;
  std::string error;
  ASSERT_EQ(streamed.open(file, s, error), 0) << error;
  ASSERT_EQ(streamed.prime(error), 0) << "refused before motion: " << error;
  const std::string journal_path = temp_dir() + "/far.journal";
  std::unique_ptr<control::Journal> journal = control::Journal::create(journal_path, streamed.id(), error);
  ASSERT_TRUE(journal) << error;
  control::MemoryOutputs out;
  const simulated::SimMachineResult r = run(streamed.source(), out, journal.get());
  ASSERT_EQ(r.run.state, control::State::fault) << r.run.reason;
  const std::size_t bad_line = 2 + 52 * 40 + 2;  // the G1 X500 line
  EXPECT_NE(r.run.reason.find("job: " + file + ":" + std::to_string(bad_line) + ": outside the soft limits"),
            std::string::npos)
      << r.run.reason;
  EXPECT_GT(r.run.completed_this_run, 1000u) << "the cut had gone on";
  EXPECT_FALSE(r.board.torch);
  journal.reset();
  control::JournalState st;
  ASSERT_TRUE(control::Journal::read(journal_path, st, error)) << error;
  EXPECT_EQ(st.last_completed + 1, static_cast<std::int64_t>(r.run.completed_this_run));
}

// A short bad job is refused before anything moves, FILE:LINE, as before.
TEST(StreamedJob, AShortBadJobIsRefusedBeforeMotion) {
  const std::string file = zigzags_file("short.ngc", 2, "G0 X0 Y0\nM3 S1\nG1 X500 Y0 F3000\nM5\n");
  control::StreamedJobSetup s = setup(false, false);
  motion::SoftLimits<double> limits;
  limits.on[0] = true;
  limits.min[0] = -1;
  limits.max[0] = 100;
  s.limits = limits;
  control::StreamedJob streamed;
  std::string error;
  ASSERT_EQ(streamed.open(file, s, error), 0) << error;
  EXPECT_EQ(streamed.prime(error), 2);
  EXPECT_EQ(error.rfind(file + ":" + std::to_string(2 + 52 * 2 + 2) + ": outside the soft limits", 0), 0u) << error;
}

}  // namespace
}  // namespace kerf::test
