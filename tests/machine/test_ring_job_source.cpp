// A point file streamed end to end: the producer thread reads and fits it
// (control/job_stream.hpp), the controller pulls the segments from its ring
// (control/ring_job_source.hpp) and the first one runs on the board before
// the file has been read to its end. The run cuts what the whole-job run cuts.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "control/point_job_pass.hpp"
#include "control/ring_job_source.hpp"
#include "simulated/sim_machine.hpp"
#include "simulated/sim_plant.hpp"
#include "fake_gpio.hpp"

namespace kerf::test {
namespace {

constexpr int kPoints = 3200;  // more segments than the ring holds: the producer must wait

// A zigzag: every point a corner, so about one segment a point; `tail` after it.
std::string zigzag_file(const char* name = "zigzag.txt", const char* tail = "") {
  const std::string dir =
      std::filesystem::temp_directory_path() / ("kerf_ring_source_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + name;
  std::ofstream f(path);
  char line[64];
  for (int k = 0; k < kPoints; ++k) {
    std::snprintf(line, sizeof line, "%.3f %.3f\n", 0.2 * k, (k % 2) * 0.3);
    f << line;
  }
  f << tail;
  return path;
}

control::JobStreamSetup setup() {
  control::JobStreamSetup s;
  s.criterion = job::Criterion::vertex;
  s.tol = 0.01;
  s.window = 64;
  s.feed_mm_s = 200.0;
  return s;
}

// The first pass: the same producer to its end, every segment kept (the oracle).
control::Job whole_job(const std::string& file) {
  static control::JobRing ring;
  control::PointFileProducer producer;
  std::string error;
  EXPECT_TRUE(producer.start(file, setup(), ring, error)) << error;
  control::Job job;
  job.paths.emplace_back();
  control::StreamItem item;
  for (;;) {
    if (!ring.try_pop(item)) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      continue;
    }
    if (item.kind != control::StreamItem::Kind::segment) break;
    if (job.paths[0].segments.empty()) job.paths[0].start = item.seg.from;
    job.paths[0].segments.push_back(item.seg.cmd);
  }
  EXPECT_EQ(item.kind, control::StreamItem::Kind::end) << producer.error();
  producer.join();
  return job;
}

simulated::SimMachineResult run(control::JobSource& source, const std::function<void(const sim::TraceSample&)>& sink,
                                control::Journal* journal = nullptr, const control::ResumePoint& from = {},
                                std::vector<simulated::BoardFault> faults = {}) {
  FakeGpio gpio;
  control::ControllerConfig cfg;
  cfg.pierce_delay_s = 0.05;
  cfg.rapid_feed_mm_s = 400.0;
  simulated::SimMachineConfig m;
  m.trace_sink = sink;
  m.faults = std::move(faults);
  std::string error;
  std::unique_ptr<simulated::SimPlant> plant = simulated::make_modbus_plant(m, cfg.link_watchdog_s, error);
  EXPECT_TRUE(plant != nullptr) << error;
  if (!plant) return {};
  return simulated::run_sim_machine(source, cfg, m, *plant, gpio, journal, from);
}

TEST(RingJobSource, TheFirstSegmentRunsBeforeTheFileIsReadAndTheCutIsTheWholeJobs) {
  const std::string file = zigzag_file();
  const control::Job job = whole_job(file);
  const std::size_t n = job.paths[0].segments.size();
  ASSERT_GT(n, control::JobRing::kCapacity + 64) << "the ring must fill";

  control::JobSummary summary;
  std::string error;
  ASSERT_TRUE(control::first_pass(file, setup(), summary, error)) << error;
  EXPECT_EQ(summary.segments, n);

  control::WholeJobSource whole(job);
  Vec2<double> whole_end{};
  const simulated::SimMachineResult a = run(whole, [&](const sim::TraceSample& s) { whole_end = s.pos; });

  static control::JobRing ring;
  control::PointFileProducer producer;
  ASSERT_TRUE(producer.start(file, setup(), ring, error)) << error;
  control::RingJobSource streamed(ring, summary, producer.error());
  std::uint64_t read_at_first = 0;
  Vec2<double> streamed_end{};
  const simulated::SimMachineResult b = run(streamed, [&](const sim::TraceSample& s) {
    if (s.seq != 0 && read_at_first == 0) read_at_first = producer.points_read();
    streamed_end = s.pos;
  });
  producer.join();

  ASSERT_EQ(a.setup_error, "");
  ASSERT_EQ(b.setup_error, "");
  std::printf("%zu segments, %.2f s simulated in %.3f s; %llu of %d points read when the first segment ran\n", n,
              b.sim_s, b.wall_s, static_cast<unsigned long long>(read_at_first), kPoints);
  ASSERT_EQ(a.run.state, control::State::done) << a.run.reason;
  ASSERT_EQ(b.run.state, control::State::done) << b.run.reason;
  EXPECT_GT(read_at_first, 0u);
  EXPECT_LT(read_at_first, static_cast<std::uint64_t>(kPoints)) << "the whole file was read before the first segment ran";
  EXPECT_EQ(b.executed, a.executed);
  EXPECT_EQ(b.executed.size(), n);
  EXPECT_EQ(b.run.completed_this_run, n);
  EXPECT_EQ(streamed.popped(), n);
  EXPECT_EQ(streamed_end, whole_end);
  EXPECT_LT(distance(streamed_end, job.paths[0].segments.back().end), 1e-3);
}

// A streamed run stopped by a drive fault, then resumed from its journal with
// a new producer: the source skips to the journal's segment; each segment is cut once.
TEST(RingJobSource, AStreamedRunResumesFromTheJournalsSegment) {
  const std::string file = zigzag_file();
  control::JobSummary summary;
  std::string error;
  ASSERT_TRUE(control::first_pass(file, setup(), summary, error)) << error;
  const std::string path = std::filesystem::path(file).parent_path() / "journal";
  std::unique_ptr<control::Journal> journal = control::Journal::create(path, summary.id, error);
  ASSERT_TRUE(journal) << error;
  std::size_t first_run = 0;
  {
    static control::JobRing ring;
    control::PointFileProducer producer;
    ASSERT_TRUE(producer.start(file, setup(), ring, error)) << error;
    control::RingJobSource streamed(ring, summary, producer.error());
    const simulated::SimMachineResult r =
        run(streamed, [](const sim::TraceSample&) {}, journal.get(), {},
            {{simulated::BoardFaultKind::drive_fault, 70.0, 0.0}});
    ASSERT_EQ(r.setup_error, "");
    ASSERT_EQ(r.run.state, control::State::fault) << r.run.reason;
    first_run = r.executed.size();
  }  // the producer stops with its source
  ASSERT_GT(first_run, control::RingJobSource::kHistory) << "the resume skips past the first ring";
  ASSERT_LT(first_run, summary.segments);
  journal.reset();
  std::unique_ptr<control::Journal> again = control::Journal::resume(path, summary.id, error);
  ASSERT_TRUE(again) << error;
  static control::JobRing ring2;
  control::PointFileProducer producer;
  ASSERT_TRUE(producer.start(file, setup(), ring2, error)) << error;
  control::RingJobSource streamed(ring2, summary, producer.error());
  const control::ResumePoint rp = control::resume_point(streamed, again->state());
  EXPECT_EQ(rp.first, static_cast<std::size_t>(again->state().last_completed + 1));
  const simulated::SimMachineResult r2 = run(streamed, [](const sim::TraceSample&) {}, again.get(), rp);
  producer.join();
  ASSERT_EQ(r2.setup_error, "");
  EXPECT_EQ(r2.run.state, control::State::done) << r2.run.reason;
  EXPECT_EQ(again->state().executed_total, summary.segments);
  EXPECT_EQ(again->state().duplicates, 0u);
  EXPECT_TRUE(again->state().finished);
  // Another file's id is refused.
  control::JobSummary other;
  ASSERT_TRUE(control::first_pass(zigzag_file("other.txt", "700 0\n"), setup(), other, error)) << error;
  again.reset();
  EXPECT_FALSE(control::Journal::resume(path, other.id, error));
}

// The first pass: the id follows the file's bytes and the fit's settings; a
// bad line is refused before anything moves.
TEST(RingJobSource, TheFirstPassIdentifiesTheJobAndRefusesABadLine) {
  control::JobSummary a, b, c, bad;
  std::string error;
  ASSERT_TRUE(control::first_pass(zigzag_file(), setup(), a, error)) << error;
  ASSERT_TRUE(control::first_pass(zigzag_file("more.txt", "700 0\n"), setup(), b, error)) << error;
  control::JobStreamSetup finer = setup();
  finer.tol = 0.005;
  ASSERT_TRUE(control::first_pass(zigzag_file(), finer, c, error)) << error;
  EXPECT_GE(b.segments, a.segments);
  EXPECT_NE(a.id.hash, b.id.hash);
  EXPECT_NE(a.id.hash, c.id.hash);
  const std::string file = zigzag_file("bad.txt", "1.0 oops\n");
  EXPECT_FALSE(control::first_pass(file, setup(), bad, error));
  EXPECT_EQ(error.rfind(file + ":" + std::to_string(kPoints + 1) + ":", 0), 0u) << error;
}

// A bad line met while cutting (after the first pass would have refused it,
// if the file changed under the run): a fault, torch off, progress kept.
TEST(RingJobSource, ABadLineMetWhileCuttingIsAFaultWithTheTorchOff) {
  const std::string file = zigzag_file("bad.txt", "1.0 oops\n");
  static control::JobRing ring;
  control::PointFileProducer producer;
  std::string error;
  ASSERT_TRUE(producer.start(file, setup(), ring, error)) << error;
  control::RingJobSource streamed(ring, {control::JobId{1, 1}, 1600}, producer.error());
  bool torch_last = true;
  const simulated::SimMachineResult r = run(streamed, [&](const sim::TraceSample& s) { torch_last = s.torch; });
  producer.join();
  ASSERT_EQ(r.setup_error, "");
  EXPECT_EQ(r.run.state, control::State::fault);
  EXPECT_NE(r.run.reason.find("job: " + file + ":" + std::to_string(kPoints + 1) + ":"), std::string::npos)
      << r.run.reason;
  EXPECT_GT(r.run.completed_this_run, control::JobRing::kCapacity / 2) << "the cut had started";
  EXPECT_FALSE(torch_last);
}

// A file that shrank after the first pass: a fault, never a short "done".
TEST(RingJobSource, AStreamShorterThanTheFirstPassIsAFault) {
  const std::string file = zigzag_file("short.txt");
  control::JobSummary summary;
  std::string error;
  ASSERT_TRUE(control::first_pass(file, setup(), summary, error)) << error;
  summary.segments += 10;  // as if the file had lost its last lines since
  static control::JobRing ring;
  control::PointFileProducer producer;
  ASSERT_TRUE(producer.start(file, setup(), ring, error)) << error;
  control::RingJobSource streamed(ring, summary, producer.error());
  const simulated::SimMachineResult r = run(streamed, [](const sim::TraceSample&) {});
  producer.join();
  EXPECT_EQ(r.run.state, control::State::fault);
  EXPECT_NE(r.run.reason.find("the first pass counted"), std::string::npos) << r.run.reason;
}

}  // namespace
}  // namespace kerf::test
