// The controller reads its job through a JobSource (control/job_source.hpp):
// one path at a time, each path's segments in order. A source that is not
// ready yet (a stream's producer behind) makes it wait, never skip or repeat.
#include <gtest/gtest.h>

#include "simulated/sim_machine.hpp"
#include "simulated/sim_plant.hpp"
#include "fake_gpio.hpp"

namespace kerf::test {
namespace {

hal::SegmentCommand line_to(Vec2<double> end) {
  hal::SegmentCommand s;
  s.kind = SegmentKind::line;
  s.end = end;
  s.feed = 100.0;
  return s;
}

// Three paths of short lines, and a dwell and an output between them.
control::Job three_paths() {
  control::Job job;
  for (int p = 0; p < 3; ++p) {
    control::CutPath c;
    c.start = {20.0 * p, 0};
    for (int i = 1; i <= 6; ++i) c.segments.push_back(line_to({20.0 * p + i, (i % 2) * 0.5}));
    job.paths.push_back(c);
  }
  control::JobAction out;
  out.kind = job::CanonKind::digital_out;
  out.index = 2;
  out.value = 1;
  out.before_path = 1;
  control::JobAction dwell;
  dwell.kind = job::CanonKind::dwell;
  dwell.value = 0.05;
  dwell.before_path = 2;
  job.actions = {out, dwell};
  return job;
}

// A whole job handed out as a slow stream: each path only on the third
// time it is asked for, each segment only every other time.
class TrickleSource final : public control::JobSource {
 public:
  explicit TrickleSource(const control::Job& job) : whole_(job) {}
  control::JobId id() const override { return whole_.id(); }
  std::size_t segment_count() const override { return whole_.segment_count(); }
  std::size_t path_count() const override { return whole_.path_count(); }
  std::size_t max_moves() const override { return whole_.max_moves(); }
  control::SegmentPlace locate(std::size_t k) override {
    located_ = true;
    return whole_.locate(k);
  }
  const control::PathHead* open(std::size_t p) override {
    if (!located_ && ++open_asks_ % 3 != 0) {  // the path locate() gave is there (locate() waits for it)
      ++withheld;
      return nullptr;
    }
    located_ = false;
    asked_ = 0;
    return whole_.open(p);
  }
  control::Pull segment(std::size_t i, const hal::SegmentCommand*& out) override {
    EXPECT_GE(i + 1, asked_) << "a segment asked again";
    asked_ = i + 1;
    if (++segment_asks_ % 2 != 0) {
      ++withheld;
      return control::Pull::later;
    }
    return whole_.segment(i, out);
  }
  const control::JobAction* action(std::size_t a) override { return whole_.action(a); }
  int withheld = 0;

 private:
  control::WholeJobSource whole_;
  unsigned open_asks_ = 0, segment_asks_ = 0;
  std::size_t asked_ = 0;
  bool located_ = false;
};

simulated::SimMachineResult run(control::JobSource& source, control::MemoryOutputs& outputs) {
  FakeGpio gpio;
  control::ControllerConfig cfg;
  cfg.pierce_delay_s = 0.05;
  cfg.rapid_feed_mm_s = 400.0;
  cfg.outputs = &outputs;
  const simulated::SimMachineConfig m;
  std::string error;
  std::unique_ptr<simulated::SimPlant> plant = simulated::make_modbus_plant(m, cfg.link_watchdog_s, error);
  EXPECT_TRUE(plant != nullptr) << error;
  if (!plant) return {};
  return simulated::run_sim_machine(source, cfg, m, *plant, gpio, nullptr, {});
}

TEST(JobSource, ASlowSourceCutsTheSameSegmentsAsTheWholeJob) {
  const control::Job job = three_paths();
  control::WholeJobSource whole(job);
  control::MemoryOutputs out_whole, out_slow;
  const simulated::SimMachineResult a = run(whole, out_whole);
  TrickleSource slow(job);
  const simulated::SimMachineResult b = run(slow, out_slow);
  ASSERT_EQ(a.setup_error, "");
  ASSERT_EQ(a.run.state, control::State::done) << a.run.reason;
  ASSERT_EQ(b.setup_error, "");
  ASSERT_EQ(b.run.state, control::State::done) << b.run.reason;
  EXPECT_GT(slow.withheld, 0);
  std::vector<std::int64_t> all(job.paths.size() * 6);
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<std::int64_t>(k);
  EXPECT_EQ(a.executed, all);
  EXPECT_EQ(b.executed, all);
  EXPECT_EQ(b.run.pierces, 3u);
  EXPECT_EQ(b.run.completed_this_run, all.size());
  ASSERT_EQ(b.run.actions.size(), 2u);  // the output, then the dwell
  EXPECT_GE(b.run.actions[1].duration_s, 0.05 - 1e-9);
  EXPECT_EQ(out_slow.digital, out_whole.digital);
  EXPECT_NEAR(b.trace.back().pos.x, 46.0, 1e-3);
}

TEST(JobSource, AResumedRunLocatesItsSegmentInTheSource) {
  const control::Job job = three_paths();
  control::WholeJobSource whole(job);
  control::JournalState st;
  st.last_completed = 8;  // path 1's third segment done
  const control::ResumePoint from = control::resume_point(whole, st);
  EXPECT_EQ(from.first, 9u);
  EXPECT_EQ(from.from, job.paths[1].segments[2].end);
  st.last_completed = 17;
  EXPECT_TRUE(control::resume_point(whole, st).done);
}

}  // namespace
}  // namespace kerf::test
