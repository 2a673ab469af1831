// The real-time cycle allocates nothing: Controller::cycle (with the Modbus
// board link's status/push/command inside it, and the journal queued to its
// writer) over a whole job with z moves, pierces and a journal, and
// CspSegmentLink::cycle over a job with z moves, its rings wrapping and its
// sink drained by another thread. This binary replaces the global operator
// new and counts per thread, only while the cycle runs on the test thread:
// the board's server thread, the journal writer and the sink's drain thread
// are not real-time and may allocate.
#include <gtest/gtest.h>

#include <cstdio>

#include "alloc_trap.hpp"
#include "control/streamed_job.hpp"
#include "cycle_rig.hpp"
#include "kerf/hal/can/csp_segment_link.hpp"

namespace kerf::test {
namespace {

std::string temp_journal(const char* name) {
  return ::testing::TempDir() + "kerf_cycle_" + std::to_string(::getpid()) + "_" + name + ".journal";
}

TEST(CycleAllocations, CountingWorks) {  // the checks below could fail
  alloc_trap_start();
  std::vector<int> v(10);
  alloc_trap_pause();
  EXPECT_EQ(alloc_trap_count(), 1);
}

TEST(CycleAllocations, ControllerCycleOverModbusWithJournalDoesNotAllocate) {
  const std::string path = temp_journal("ctl");
  CycleRig rig(quick_controller(), nullptr);  // the job, for its id
  std::string err;
  auto journal = control::Journal::create(path, rig.job.id(), err);
  ASSERT_TRUE(journal) << err;
  CycleRig run(quick_controller(), journal.get());
  run.ctl->start({});
  long cycles = 0;
  alloc_trap_start();
  alloc_trap_pause();
  const bool done = run.run(60.0, [&](bool on) {
    on ? alloc_trap_resume() : alloc_trap_pause();
    cycles += on;
  });
  ASSERT_TRUE(done);
  const control::RunReport& r = run.ctl->report();
  ASSERT_EQ(r.state, control::State::done) << r.reason;
  EXPECT_EQ(r.completed_this_run, 12u);
  EXPECT_EQ(r.pierces, 3u);
  EXPECT_EQ(r.z_moves, 9u);
  EXPECT_EQ(run.gpio.torch_ons, 3);
  std::printf("Controller::cycle: %ld allocations in %ld cycles (%.1f s simulated)\n", alloc_trap_count(), cycles, run.t);
  EXPECT_EQ(alloc_trap_count(), 0);
  // The writer synced everything before the run finished.
  EXPECT_EQ(journal->state().last_completed, 11);
  EXPECT_TRUE(journal->state().finished);
  std::remove(path.c_str());
}

// The same over kerf run's streamed job (control/streamed_job.hpp): a
// G-code program with z moves before and after each path, a dwell after each
// and M2 at the end (the actions' log is reserved, its texts in place), more
// segments than the producer's ring holds. Its producer thread reads, fits and allocates;
// the cycle only pops the ring.
TEST(CycleAllocations, ControllerCycleOverAStreamedJobDoesNotAllocate) {
  const std::string file = ::testing::TempDir() + "kerf_cycle_" + std::to_string(::getpid()) + "_stream.ngc";
  {
    std::FILE* f = std::fopen(file.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fprintf(f, "G21 G90\n");
    for (int p = 0; p < 24; ++p) {
      const double x0 = 12.0 * (p % 6), y0 = 3.0 * (p / 6);
      std::fprintf(f, "G0 Z5\nG0 X%.3f Y%.3f\nG1 Z1.5 F600\nM3 S1\n", x0, y0);
      for (int k = 1; k <= 48; ++k) std::fprintf(f, "G1 X%.3f Y%.3f F3000\n", x0 + 0.2 * k, y0 + (k % 2) * 0.3);
      std::fprintf(f, "M5\nG0 Z10\nG4 P0.01\n");
    }
    std::fprintf(f, "M2\n");
    std::fclose(f);
  }
  control::StreamedJobSetup s;
  s.criterion = job::Criterion::band;
  s.tol = 0.01;
  s.feed_mm_s = 50.0;
  s.max_feed_mm_s = 100.0;
  s.interp.z_axis = true;
  control::StreamedJob streamed;
  std::string err;
  ASSERT_EQ(streamed.open(file, s, err), 0) << err;
  ASSERT_EQ(streamed.prime(err), 0) << err;
  const std::string path = temp_journal("stream");
  auto journal = control::Journal::create(path, streamed.id(), err);
  ASSERT_TRUE(journal) << err;
  CycleRig run(quick_controller(), journal.get(), &streamed.source());
  run.ctl->start({});
  long cycles = 0;
  alloc_trap_start();
  alloc_trap_pause();
  const bool done = run.run(300.0, [&](bool on) {
    on ? alloc_trap_resume() : alloc_trap_pause();
    cycles += on;
  });
  ASSERT_TRUE(done);
  const control::RunReport& r = run.ctl->report();
  ASSERT_EQ(r.state, control::State::done) << r.reason;
  const control::StreamTotals t = streamed.totals();
  EXPECT_GT(t.segments, 1024u) << "more than the ring holds";
  EXPECT_EQ(r.completed_this_run, t.segments);
  EXPECT_EQ(r.pierces, 24u);
  EXPECT_GE(r.z_moves, 48u);
  EXPECT_EQ(r.action_counts.dwells, 24u);
  EXPECT_EQ(r.action_counts.run, 25u) << "24 dwells and the program's end";
  EXPECT_EQ(r.actions.size(), 25u);
  std::printf("Controller::cycle over a streamed job: %ld allocations in %ld cycles (%zu segments, %.1f s simulated)\n",
              alloc_trap_count(), cycles, t.segments, run.t);
  EXPECT_EQ(alloc_trap_count(), 0);
  EXPECT_TRUE(journal->state().finished);
  std::remove(path.c_str());
  std::remove(file.c_str());
}

// Three drives whose actual position follows the target in the same SYNC.
class FollowingAxes final : public hal::AxisLink {
 public:
  std::size_t axis_count() const override { return 3; }
  double period_s() const override { return 0.001; }
  hal::AxisError bring_up() override { return hal::AxisError::none; }
  hal::AxisError enable() override { return hal::AxisError::none; }
  hal::AxisError disable() override { return hal::AxisError::none; }
  hal::AxisError fault_reset() override { return hal::AxisError::none; }
  void set_target(std::size_t a, std::int32_t counts) override { axes_[a].target = counts; }
  hal::AxisError cycle() override {
    ++counters_.cycles;
    for (auto& a : axes_) {
      a.actual = a.target;
      a.feedback_cycle = counters_.cycles;
    }
    return hal::AxisError::none;
  }
  const hal::AxisState& axis(std::size_t i) const override { return axes_[i]; }
  const hal::AxisCounters& counters() const override { return counters_; }
  const char* last_error() const override { return ""; }

 private:
  hal::AxisState axes_[3]{};
  hal::AxisCounters counters_{};
};

TEST(CycleAllocations, CspCycleWithRingsAndSinkDoesNotAllocate) {
  FollowingAxes axes;
  hal::CspConfig c;
  c.z = {0.001, 30.0, 500.0};
  c.trace_capacity = 256;  // wraps many times over the job
  c.executed_capacity = 8;
  c.sink_capacity = 1 << 16;  // more than the job's samples: nothing dropped whatever the drain thread does
  std::string err;
  auto link = hal::CspSegmentLink::create(axes, c, err);
  ASSERT_TRUE(link) << err;
  std::vector<hal::CspSample> sunk;
  std::vector<std::uint32_t> sunk_done;
  link->run_sink([&](const hal::CspRecord& r) {
    if (r.executed) sunk_done.push_back(r.seq);
    else sunk.push_back(r.sample);
  }, 0.001);
  // 40 segments: lines with a z move every tenth.
  std::vector<hal::SegmentCommand> segs;
  for (std::uint32_t k = 1; k <= 40; ++k) {
    hal::SegmentCommand s = line_seg({static_cast<double>(k), static_cast<double>(k % 3)}, 80.0);
    if (k % 10 == 0) {
      s = z_seg(k % 20 == 0 ? 2.0 : 4.0);
      s.end = segs.back().end;
    }
    s.seq = k;
    segs.push_back(s);
  }
  hal::BoardStatus st;
  std::size_t next = 0;
  long cycles = 0;
  alloc_trap_start();
  alloc_trap_pause();
  for (int i = 0; i < 200000 && st.state != hal::BoardState::done; ++i) {
    alloc_trap_resume();
    while (next < segs.size() && link->push(segs[next], st) == hal::LinkError::none) ++next;
    if (i == 0) link->command(hal::Command::start);
    if (next == segs.size()) link->command(hal::Command::finish);
    link->cycle();
    link->status(st);
    alloc_trap_pause();
    ++cycles;
    ASSERT_NE(st.state, hal::BoardState::fault) << link->last_error();
  }
  link->stop_sink();
  ASSERT_EQ(st.state, hal::BoardState::done);
  std::printf("CspSegmentLink push/cycle/status: %ld allocations in %ld cycles\n", alloc_trap_count(), cycles);
  EXPECT_EQ(alloc_trap_count(), 0);
  // The rings keep the last ones; the sink got all of them.
  EXPECT_EQ(link->sink_dropped(), 0u);
  ASSERT_EQ(sunk.size(), link->trace_total());
  ASSERT_GT(sunk.size(), 1000u);
  const std::vector<hal::CspSample> ring = link->trace();
  ASSERT_EQ(ring.size(), 256u);
  for (std::size_t i = 0; i < ring.size(); ++i) EXPECT_EQ(ring[i].cycle, sunk[sunk.size() - 256 + i].cycle);
  for (std::size_t i = 1; i < sunk.size(); ++i) ASSERT_EQ(sunk[i].cycle, sunk[i - 1].cycle + 1);
  std::vector<std::uint32_t> all;
  for (std::uint32_t k = 1; k <= 40; ++k) all.push_back(k);
  EXPECT_EQ(sunk_done, all);
  EXPECT_EQ(link->executed(), (std::vector<std::uint32_t>{33, 34, 35, 36, 37, 38, 39, 40}));
}

}  // namespace
}  // namespace kerf::test
