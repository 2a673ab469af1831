// The controller on the simulated machine, driven cycle by cycle with a fake
// GPIO: the path sequence, the torch, faults and resume.
#include <gtest/gtest.h>

#include <cmath>

#include "simulated/sim_machine.hpp"
#include "fake_gpio.hpp"

namespace kerf::test {
namespace {

using control::State;

// Two paths: an L of two lines, then a half circle of radius 10.
control::Job two_paths() {
  control::Job job;
  auto seg = [](Vec2<double> end, SegmentKind kind = SegmentKind::line, Vec2<double> c = {}, int dir = 0) {
    hal::SegmentCommand s;
    s.kind = kind;
    s.end = end;
    s.centre = c;
    s.dir = static_cast<std::int8_t>(dir);
    s.feed = 50.0;
    return s;
  };
  control::CutPath a;
  a.start = {0, 0};
  a.segments = {seg({40, 0}), seg({40, 30})};
  control::CutPath b;
  b.start = {60, 0};
  b.segments = {seg({80, 0}, SegmentKind::arc, {70, 0}, 1), seg({100, 0})};
  job.paths = {a, b};
  return job;
}

control::ControllerConfig fast_cut() {
  control::ControllerConfig c;
  c.pierce_delay_s = 0.1;
  c.arc_ok_timeout_s = 0.5;
  c.rapid_feed_mm_s = 200.0;
  return c;
}

TEST(Controller, CutsEveryPathOnceWithTheTorchOnlyOnWhileCutting) {
  const control::Job job = two_paths();
  FakeGpio gpio;
  simulated::SimMachineConfig m;
  const auto r = simulated::run_sim_machine(job, fast_cut(), m, gpio, nullptr, {});
  ASSERT_EQ(r.setup_error, "");
  EXPECT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.run.completed_this_run, 4u);
  EXPECT_EQ(r.executed, (std::vector<std::int64_t>{0, 1, 2, 3}));
  EXPECT_EQ(r.run.pierces, 2u);
  ASSERT_EQ(gpio.changes.size(), 4u);  // on, off, on, off
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(gpio.changes[i].on, i % 2 == 0);
  // Torch on only at rest at a pierce point or while cutting a segment (the
  // board reports no segment in the period that completes the last one).
  for (std::size_t i = 1; i < r.trace.size(); ++i) {
    const auto& s = r.trace[i];
    if (!s.torch) continue;
    if (s.seq == 0 && r.trace[i - 1].seq == 0) {
      EXPECT_EQ(distance(s.pos, r.trace[i - 1].pos), 0.0) << "torch on while moving on a rapid at t=" << s.t_s;
    }
  }
  EXPECT_FALSE(r.trace.back().torch);
  EXPECT_LT(distance(r.trace.back().pos, Vec2<double>{100, 0}), 1e-3);
}

}  // namespace
}  // namespace kerf::test

namespace kerf::test {
namespace {

// The first trace sample at or after t.
std::size_t sample_at(const simulated::SimMachineResult& r, double t) {
  std::size_t i = 0;
  while (i + 1 < r.trace.size() && r.trace[i].t_s < t) ++i;
  return i;
}

// Torch off in the cycle the input tripped, motion stopped on the path
// within the braking distance of the feed (v^2 / 2a, plus one cycle).
void expect_safe_stop(const simulated::SimMachineResult& r, const FakeGpio& gpio, double trip_t) {
  ASSERT_FALSE(gpio.changes.empty());
  EXPECT_FALSE(gpio.changes.back().on);
  EXPECT_GE(gpio.changes.back().t, trip_t);
  EXPECT_LT(gpio.changes.back().t, trip_t + 0.002 + 1e-9) << "torch off later than one cycle";
  const simulated::SimMachineConfig defaults;
  const double v = 50.0, a = defaults.motion.accel_mm_s2;
  const Vec2<double> at_trip = r.trace[sample_at(r, trip_t)].pos;
  EXPECT_LE(distance(at_trip, r.run.stopped_at), v * v / (2 * a) + v * 0.002 + 1e-6);
  EXPECT_FALSE(r.trace.back().torch);
  EXPECT_EQ(distance(r.trace.back().pos, r.trace[r.trace.size() - 2].pos), 0.0) << "still moving";
}

TEST(ControllerFaults, EStopMidArcStopsOnThePathAndKeepsTheCutPoint) {
  const control::Job job = two_paths();
  FakeGpio gpio;
  // Path 1 pierces at about 2.1 s; the arc takes 0.63 s.
  gpio.at(2.4, [](FakeGpio& g) { g.inputs.estop = true; });
  const auto r = simulated::run_sim_machine(job, fast_cut(), {}, gpio, nullptr, {});
  ASSERT_EQ(r.setup_error, "");
  EXPECT_EQ(r.run.state, State::estop);
  EXPECT_EQ(r.run.reason, "E-stop");
  expect_safe_stop(r, gpio, 2.4);
  EXPECT_EQ(r.run.last_completed, 1);  // the first path, not the arc
  ASSERT_TRUE(r.run.has_cut_to);
  EXPECT_EQ(r.run.cut_to.segment, 2u);
  EXPECT_LT(std::abs(distance(r.run.cut_to.at, Vec2<double>{70, 0}) - 10.0), 2e-3);  // on the arc
  EXPECT_EQ(distance(r.run.cut_to.at, r.run.torch_off_at), 0.0);
}

TEST(ControllerFaults, ArcLostWhileCuttingIsAFault) {
  const control::Job job = two_paths();
  FakeGpio gpio;
  gpio.at(0.8, [](FakeGpio& g) { g.arc_lost = true; });
  const auto r = simulated::run_sim_machine(job, fast_cut(), {}, gpio, nullptr, {});
  EXPECT_EQ(r.run.state, State::fault);
  EXPECT_NE(r.run.reason.find("arc-OK lost while cutting segment 0"), std::string::npos) << r.run.reason;
  expect_safe_stop(r, gpio, 0.8);
}

TEST(ControllerFaults, NoArcAtThePierceTimesOutWithoutMoving) {
  const control::Job job = two_paths();
  FakeGpio gpio;
  gpio.arc_works = false;
  const auto r = simulated::run_sim_machine(job, fast_cut(), {}, gpio, nullptr, {});
  EXPECT_EQ(r.run.state, State::fault);
  EXPECT_NE(r.run.reason.find("no arc-OK within 0.5 s"), std::string::npos) << r.run.reason;
  ASSERT_EQ(gpio.changes.size(), 2u);
  EXPECT_NEAR(gpio.changes[1].t - gpio.changes[0].t, 0.5, 0.0025);
  EXPECT_EQ(r.run.completed_this_run, 0u);
  EXPECT_EQ(distance(r.run.stopped_at, Vec2<double>{0, 0}), 0.0);
}

TEST(ControllerFaults, LimitSwitchAndDriveFaultStopTheCut) {
  const control::Job job = two_paths();
  {
    FakeGpio gpio;
    gpio.inputs.limit_count = 2;
    gpio.at(0.5, [](FakeGpio& g) { g.inputs.limit[1] = true; });
    const auto r = simulated::run_sim_machine(job, fast_cut(), {}, gpio, nullptr, {});
    EXPECT_EQ(r.run.state, State::fault);
    EXPECT_EQ(r.run.reason, "limit switch 1 hit");
    expect_safe_stop(r, gpio, 0.5);
  }
  {
    FakeGpio gpio;
    simulated::SimMachineConfig m;
    m.faults = {{simulated::BoardFaultKind::drive_fault, 0.5, 0.0}};
    const auto r = simulated::run_sim_machine(job, fast_cut(), m, gpio, nullptr, {});
    EXPECT_EQ(r.run.state, State::fault);
    EXPECT_NE(r.run.reason.find("drive-fault"), std::string::npos) << r.run.reason;
    expect_safe_stop(r, gpio, 0.5);
  }
}

TEST(ControllerFaults, FeedHoldStopsThenRepiercesWhereItStopped) {
  const control::Job job = two_paths();
  FakeGpio gpio;
  gpio.at(0.6, [](FakeGpio& g) { g.inputs.hold = true; });
  gpio.at(0.7, [](FakeGpio& g) { g.inputs.hold = false; });
  gpio.at(1.5, [](FakeGpio& g) { g.inputs.cycle_start = true; });
  gpio.at(1.6, [](FakeGpio& g) { g.inputs.cycle_start = false; });
  const auto r = simulated::run_sim_machine(job, fast_cut(), {}, gpio, nullptr, {});
  EXPECT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.executed, (std::vector<std::int64_t>{0, 1, 2, 3}));
  EXPECT_EQ(r.run.pierces, 3u);
  ASSERT_EQ(gpio.changes.size(), 6u);
  // Off once stopped (not before: the cut goes on while braking), on again at cycle start.
  const Vec2<double> off_at = r.trace[sample_at(r, gpio.changes[1].t)].pos;
  const Vec2<double> on_at = r.trace[sample_at(r, gpio.changes[2].t)].pos;
  EXPECT_EQ(distance(off_at, on_at), 0.0);
  EXPECT_GT(gpio.changes[1].t, 0.6);
  EXPECT_NEAR(gpio.changes[2].t, 1.5, 0.0021);
}

TEST(ControllerResume, StartsAtTheCutPointAndCutsTheRestOnce) {
  const control::Job job = two_paths();
  FakeGpio gpio;
  control::ResumePoint from;
  from.first = 2;
  from.from = {70, -10};  // the bottom of the arc (CCW from (60, 0))
  simulated::SimMachineConfig m;
  m.start = {5, 5};  // wherever the axes were left
  const auto r = simulated::run_sim_machine(job, fast_cut(), m, gpio, nullptr, from);
  EXPECT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.executed, (std::vector<std::int64_t>{2, 3}));
  ASSERT_EQ(gpio.changes.size(), 2u);
  EXPECT_LT(distance(r.trace[sample_at(r, gpio.changes[0].t)].pos, from.from), 1e-3);
  // Nothing of the arc before the cut point is cut again: every torch-on
  // sample lies on the arc's second half or on the last line.
  for (const auto& s : r.trace) {
    if (s.torch) {
      EXPECT_GE(s.pos.x, 70.0 - 1e-3) << s.t_s;
    }
  }
}

}  // namespace
}  // namespace kerf::test

namespace kerf::test {
namespace {

TEST(ControllerFaults, HoldDuringTheRepierceStillResumesTheHeldPath) {
  const control::Job job = two_paths();
  FakeGpio gpio;
  auto press = [&](double t, bool hal::GpioInputs::*button) {
    gpio.at(t, [button](FakeGpio& g) { g.inputs.*button = true; });
    gpio.at(t + 0.01, [button](FakeGpio& g) { g.inputs.*button = false; });
  };
  press(0.6, &hal::GpioInputs::hold);
  press(1.5, &hal::GpioInputs::cycle_start);
  press(1.54, &hal::GpioInputs::hold);  // during the re-pierce's delay
  press(2.0, &hal::GpioInputs::cycle_start);
  const auto r = simulated::run_sim_machine(job, fast_cut(), {}, gpio, nullptr, {});
  EXPECT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.executed, (std::vector<std::int64_t>{0, 1, 2, 3}));
  EXPECT_EQ(r.run.pierces, 4u);
}

// A resume point a fraction of a count, or a few counts, past a segment's
// end (the journal's cut_to is the board's position: it may lie beyond the
// end, and off the link's 1 um grid): that segment was cut whole, and the run
// goes on with the next one. Before the resumed segment went through the
// segment contract (control/resume_segment.hpp), the board got a line or arc
// whose ends coincide on its grid (a bad-segment fault), or, 2 um past the
// arc's end, an arc of sweep nearly 2 pi: a full circle cut.
TEST(ControllerResume, APointJustPastASegmentsEndResumesAtTheNextOne) {
  const control::Job job = two_paths();
  struct Case {
    std::size_t first;
    Vec2<double> at;
    std::vector<std::int64_t> executed;
  };
  const double d04 = 0.0004 / 10, d2 = 0.002 / 10;  // 0.4 and 2 um along the arc of radius 10
  const Case cases[] = {
      {0, {40.0004, 0.0001}, {1, 2, 3}},                        // past the first line's end
      {2, {70 + 10 * std::cos(d04), 10 * std::sin(d04)}, {3}},  // past the arc's end (CCW)
      {2, {70 + 10 * std::cos(d2), 10 * std::sin(d2)}, {3}},
  };
  for (const Case& c : cases) {
    FakeGpio gpio;
    control::ResumePoint from;
    from.first = c.first;
    from.from = c.at;
    const auto r = simulated::run_sim_machine(job, fast_cut(), {}, gpio, nullptr, from);
    EXPECT_EQ(r.run.state, State::done) << r.run.reason;
    EXPECT_EQ(r.executed, c.executed);
    EXPECT_EQ(r.run.completed_this_run, c.executed.size() + 1);  // the one cut whole, then the rest
    for (const auto& s : r.trace) {
      if (s.torch && c.first == 2) {  // on the last line only: no circle
        EXPECT_NEAR(s.pos.y, 0.0, 1e-3) << s.t_s;
        EXPECT_GE(s.pos.x, 80.0 - 1e-3) << s.t_s;
      }
    }
  }
}

// A resume point off the grid inside an arc: the rest of the arc, from the
// grid point nearest it, stays on the circle; the arc is completed once.
TEST(ControllerResume, AnOffGridPointInsideAnArcCutsItsRestOnTheCircle) {
  const control::Job job = two_paths();
  FakeGpio gpio;
  control::ResumePoint from;
  from.first = 2;
  const double a = -2.0;  // rad, on the arc's first half (CCW from pi to 2 pi)
  from.from = {70 + 10 * std::cos(a) + 0.00031, 10 * std::sin(a) - 0.00027};
  const auto r = simulated::run_sim_machine(job, fast_cut(), {}, gpio, nullptr, from);
  EXPECT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.executed, (std::vector<std::int64_t>{2, 3}));
  for (const auto& s : r.trace) {
    if (s.torch && s.seq == 3) {
      EXPECT_NEAR(distance(s.pos, {70, 0}), 10.0, 2e-3) << s.t_s;
    }
  }
}

// A rest that emit_on_grid splits in two (a tiny arc whose centre is off the
// grid: its sweep would change by more than 0.5 rad on the grid): two board
// segments for one job segment, which is completed once, after the second.
TEST(ControllerResume, ARestSplitInTwoCompletesItsSegmentOnce) {
  hal::SegmentCommand arc;
  arc.kind = SegmentKind::arc;
  arc.end = {0.001, 0};
  arc.centre = {0, 0.0003};
  arc.dir = 1;
  arc.feed = 5.0;
  hal::SegmentCommand line = arc;
  line.kind = SegmentKind::line;
  line.end = {0.01, 0};
  line.dir = 0;
  control::Job job;
  control::CutPath p;
  p.start = {-0.001, 0};
  p.segments = {arc, line};
  job.paths = {p};
  const control::ResumedSegment rest = control::resume_segment(arc, p.start, {-0.0010427, 0.0002478});
  ASSERT_EQ(rest.count, 2);  // the case this test is about
  FakeGpio gpio;
  control::ResumePoint from;
  from.first = 0;
  from.from = {-0.0010427, 0.0002478};
  const auto r = simulated::run_sim_machine(job, fast_cut(), {}, gpio, nullptr, from);
  EXPECT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.executed, (std::vector<std::int64_t>{0, 1}));
  EXPECT_EQ(r.run.completed_this_run, 2u);
  EXPECT_EQ(r.run.last_completed, 1);
}

}  // namespace
}  // namespace kerf::test
