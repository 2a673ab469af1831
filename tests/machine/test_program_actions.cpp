// A G-code program's actions on the simulated machine: dwell, pause and
// cycle-start, outputs, M66 with its timeout, the feed %, dry-run paths,
// and what a resumed run does with the actions before its resume point.
// Each job comes from G-code text through the interpreter, as kerf sim's.
#include <gtest/gtest.h>

#include <cmath>

#include "control/job_actions.hpp"
#include "control/program_job.hpp"
#include "fake_gpio.hpp"
#include "program_fixture.hpp"
#include "simulated/sim_machine.hpp"

namespace kerf::test {
namespace {

using control::State;
using job::CanonKind;

// The time span over which the board stood still at p with the torch off.
double rest_at(const simulated::SimMachineResult& r, Vec2<double> p) {
  double first = -1, last = -1;
  for (const auto& s : r.trace)
    if (distance(s.pos, p) < 1e-6 && !s.torch) {
      if (first < 0) first = s.t_s;
      last = s.t_s;
    }
  return last - first;
}

// The time the board is first on the given segment (1-based in the trace).
double start_of(const simulated::SimMachineResult& r, std::uint32_t seq) {
  for (const auto& s : r.trace)
    if (s.seq == seq) return s.t_s;
  return -1;
}


TEST(ProgramActions, DwellHoldsTheMachineAtRestTorchOff) {
  const control::FittedJob f = fitted("G21 G90\nG0 X0 Y0\nM3\nG1 X20 F1200\nG4 P0.75\nG1 X30\nM5\n");
  ASSERT_EQ(f.job.paths.size(), 2u);  // the dwell splits the cut: never merged away
  FakeGpio gpio;
  const auto r = simulated::run_sim_machine(f.job, fast(), {}, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  ASSERT_EQ(r.run.actions.size(), 1u);
  EXPECT_EQ(r.run.actions[0].kind, CanonKind::dwell);
  EXPECT_GE(r.run.actions[0].duration_s, 0.75 - 1e-9);
  EXPECT_LT(r.run.actions[0].duration_s, 0.75 + 0.005);
  EXPECT_GE(rest_at(r, {20, 0}), 0.75);
  EXPECT_EQ(r.run.pierces, 2u);
}

// A path that starts where the last one ended, off the count grid (0.2 um
// here): no travel at all. A travel from the board's position (rounded to
// counts) was a fraction of a count long, empty on the board: bad-segment.
TEST(ProgramActions, APathFromTheLastOnesEndOffTheCountGridNeedsNoTravel) {
  const control::FittedJob f =
      fitted("G1 X129.1062 Y-33.3832 F1500\nG4 P0.1\nG1 X129.0943 Y-33.3862 F100\nG1 X129.0851 Y-33.3949\n");
  ASSERT_EQ(f.job.paths.size(), 2u);
  FakeGpio gpio;
  const auto r = simulated::run_sim_machine(f.job, fast(), {}, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.executed.size(), f.job.segment_count());
}

TEST(ProgramActions, PauseWaitsForCycleStart) {
  const control::FittedJob f = fitted(two_cuts("M0"));
  FakeGpio gpio;
  gpio.at(3.0, [](FakeGpio& g) { g.inputs.cycle_start = true; });
  gpio.at(3.1, [](FakeGpio& g) { g.inputs.cycle_start = false; });
  const auto r = simulated::run_sim_machine(f.job, fast(), {}, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  ASSERT_EQ(r.run.actions.size(), 1u);
  EXPECT_EQ(r.run.actions[0].kind, CanonKind::pause);
  EXPECT_NEAR(r.run.actions[0].t_s + r.run.actions[0].duration_s, 3.0, 0.0025);
  EXPECT_GT(start_of(r, 2), 3.0);  // the second path only after the press
  // The torch was off for the whole pause.
  for (const auto& c : gpio.changes) {
    const bool outside = c.t < r.run.actions[0].t_s || c.t > 3.0;
    if (c.on) {
      EXPECT_TRUE(outside) << "torch on at " << c.t;
    }
  }
}

TEST(ProgramActions, SimulatedOperatorPressesCycleStartAfterItsDelay) {
  const control::FittedJob f = fitted(two_cuts("M1"));
  FakeGpio gpio;
  control::ControllerConfig c = fast();
  c.operator_delay_s = 0.4;
  const auto r = simulated::run_sim_machine(f.job, c, {}, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  ASSERT_EQ(r.run.actions.size(), 1u);
  EXPECT_NEAR(r.run.actions[0].duration_s, 0.4, 0.0025);
  EXPECT_NE(std::string(r.run.actions[0].what).find("simulated operator"), std::string::npos);
}

TEST(ProgramActions, OutputsSwitchBetweenThePathsInProgramOrder) {
  const control::FittedJob f = fitted(two_cuts("M62 P4\nM65 P5\nM68 E1 Q2.5"));
  FakeGpio gpio;
  control::MemoryOutputs outs;
  control::ControllerConfig c = fast();
  c.outputs = &outs;
  const auto r = simulated::run_sim_machine(f.job, c, {}, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(outs.digital, (std::vector<std::pair<int, bool>>{{4, true}, {5, false}}));
  EXPECT_EQ(outs.analog, (std::vector<std::pair<int, double>>{{1, 2.5}}));
  ASSERT_EQ(r.run.actions.size(), 3u);
  EXPECT_LT(r.run.actions[2].t_s, start_of(r, 2));  // before the second path's move
  EXPECT_GT(r.run.actions[0].t_s, start_of(r, 1));  // after the first path's
}

TEST(ProgramActions, M66TimesOutAndGoesOnOrEndsWhenTheInputComes) {
  const control::FittedJob f = fitted(two_cuts("M66 P0 L3 Q0.4\nM66 P1 L3 Q5"));
  FakeGpio gpio;
  control::MemoryOutputs outs;
  outs.inputs = {false, false};
  control::ControllerConfig c = fast();
  c.outputs = &outs;
  // First with both inputs low: both waits time out.
  double second_wait = -1;
  const auto probe = simulated::run_sim_machine(f.job, c, {}, gpio, nullptr, {});
  ASSERT_EQ(probe.run.actions.size(), 2u);
  EXPECT_NE(std::string(probe.run.actions[0].what).find("timed out after 0.4 s"), std::string::npos) << probe.run.actions[0].what;
  EXPECT_NEAR(probe.run.actions[0].duration_s, 0.4, 0.0025);
  EXPECT_NE(std::string(probe.run.actions[1].what).find("timed out after 5 s"), std::string::npos);
  second_wait = probe.run.actions[1].t_s;
  // Again, with input 1 raised 0.3 s into the second wait.
  FakeGpio gpio2;
  control::MemoryOutputs outs2;
  outs2.inputs = {false, false};
  c.outputs = &outs2;
  gpio2.at(second_wait + 0.3, [&outs2](FakeGpio&) { outs2.inputs[1] = true; });
  const auto r = simulated::run_sim_machine(f.job, c, {}, gpio2, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  ASSERT_EQ(r.run.actions.size(), 2u);
  EXPECT_NE(std::string(r.run.actions[1].what).find("met"), std::string::npos) << r.run.actions[1].what;
  EXPECT_NEAR(r.run.actions[1].duration_s, 0.3, 0.0025);
}

TEST(ProgramActions, FeedPercentSlowsThePathsAfterIt) {
  const control::FittedJob f = fitted(two_cuts("M67 E3 Q25"));
  ASSERT_EQ(f.job.paths.size(), 2u);
  EXPECT_DOUBLE_EQ(f.job.paths[0].segments[0].feed, 20.0);  // F1200 mm/min
  EXPECT_DOUBLE_EQ(f.job.paths[1].segments[0].feed, 5.0);   // 25 % of it
  FakeGpio gpio;
  const auto r = simulated::run_sim_machine(f.job, fast(), {}, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  double fastest = 0;  // on the second path, from the trace
  for (std::size_t i = 1; i < r.trace.size(); ++i)
    if (r.trace[i].seq == 2 && r.trace[i - 1].seq == 2)
      fastest = std::max(fastest, distance(r.trace[i].pos, r.trace[i - 1].pos) / (r.trace[i].t_s - r.trace[i - 1].t_s));
  EXPECT_GT(fastest, 4.9);
  EXPECT_LT(fastest, 5.0 + 0.01);
}

// Inside a cut the feed % splits nothing (no re-pierce): the segments after it run slower.
TEST(ProgramActions, FeedPercentInsideACutSlowsItsLaterSegmentsWithoutAPierce) {
  const control::FittedJob f = fitted("G21 G90\nG0 X0 Y0\nM3\nG1 X20 F1200\nM67 E3 Q50\nG1 Y20\nM5\n");
  ASSERT_EQ(f.job.paths.size(), 1u);
  ASSERT_EQ(f.job.paths[0].segments.size(), 2u);
  EXPECT_DOUBLE_EQ(f.job.paths[0].segments[0].feed, 20.0);
  EXPECT_DOUBLE_EQ(f.job.paths[0].segments[1].feed, 10.0);
  EXPECT_TRUE(f.job.actions.empty());
}

TEST(ProgramActions, AFileWithoutATorchWordIsADryRun) {
  const control::FittedJob f = fitted("G21 G90\nG1 X20 Y0 F1200\nG0 X0 Y10\nG1 X20\n");
  ASSERT_EQ(f.job.paths.size(), 2u);
  EXPECT_FALSE(f.job.paths[0].torch);
  FakeGpio gpio;
  gpio.arc_works = false;  // no arc is ever asked for
  const auto r = simulated::run_sim_machine(f.job, fast(), {}, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  EXPECT_EQ(r.run.pierces, 0u);
  EXPECT_TRUE(gpio.changes.empty());
  for (const auto& s : r.trace) EXPECT_FALSE(s.torch);
  EXPECT_EQ(r.run.completed_this_run, 2u);
}

TEST(ProgramActions, AResumeRunsTheActionsJustBeforeAnUncutPathAndSkipsEarlierOnes) {
  const control::FittedJob f = fitted(two_cuts("M62 P4\nG4 P0.5"));
  control::MemoryOutputs outs;
  control::ControllerConfig c = fast();
  c.outputs = &outs;
  {  // resumed at the second path's start, nothing of it cut: the dwell and the output run
    control::ResumePoint from;
    from.first = 1;
    from.from = f.job.paths[1].start;
    FakeGpio gpio;
    const auto r = simulated::run_sim_machine(f.job, c, {}, gpio, nullptr, from);
    ASSERT_EQ(r.run.state, State::done) << r.run.reason;
    EXPECT_EQ(r.run.actions.size(), 2u);
    EXPECT_EQ(outs.digital.size(), 1u);
  }
  {  // resumed inside the second path: the actions before it are not run again, the output is set again
    const control::FittedJob g = fitted(two_cuts("M62 P4\nG4 P0.5\nG0 X0 Y10\nM3\nG1 X20\nM5\nG0 X0 Y30"));
    outs.digital.clear();
    control::ResumePoint from;
    from.first = 1;
    from.from = {10, 10};
    FakeGpio gpio;
    const auto r = simulated::run_sim_machine(g.job, c, {}, gpio, nullptr, from);
    ASSERT_EQ(r.run.state, State::done) << r.run.reason;
    EXPECT_TRUE(r.run.actions.empty());
    EXPECT_EQ(outs.digital, (std::vector<std::pair<int, bool>>{{4, true}}));
  }
}

// The report lists the constructs and how each was handled, and says when a
// run was a dry run.
TEST(ProgramReport, ListsTheConstructsAndSaysDryRun) {
  const std::string text = "G21 G90 G54 G64 P0.01\nG1 X20 Y0 F1200\nG4 P0.1\nG1 X30\nM150\nM2\n";
  const job::GcodeFile g = job::parse_gcode(text, "r.ngc");
  job::Interpretation it;
  job::GcodeProgram prog;
  std::string error;
  ASSERT_TRUE(job::interpret(g, {}, {}, it, error)) << error;
  ASSERT_TRUE(job::build_program(g, {}, it, prog, error)) << error;
  control::FittedJob f;
  ASSERT_EQ(control::fit_program_or_say(prog, job::Criterion::band, 0.01, 50.0, 200.0, f), 0);
  FakeGpio gpio;
  const auto r = simulated::run_sim_machine(f.job, fast(), {}, gpio, nullptr, {});
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  control::RunSummary sum = control::summarise_run(r.run, f.job.paths.size(), "modbus-tcp", false, nullptr);
  control::describe_program(prog, sum);
  const std::string line = control::format_run_summary(sum);
  EXPECT_NE(line.find("; dry run (no M3/M4 in the program): torch off"), std::string::npos) << line;
  EXPECT_NE(line.find("; 1 dwells, 0 pauses, 2 program actions"), std::string::npos) << line;
  EXPECT_NE(line.find("kerf sim: G-code: F run (1), G1 run (2), G21 recorded (1), G4 run (1), G54 run (1), "
                      "G64 P recorded (1), G90 recorded (1), M150 ignored (1), M2 run (1)\n"),
            std::string::npos)
      << line;
  const std::string json = control::format_run_json(sum);
  EXPECT_NE(json.find("\"dry_run\": true"), std::string::npos);
  EXPECT_NE(json.find("{\"name\": \"M150\", \"handling\": \"ignored\", \"count\": 1, \"first_line\": 5}"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"notes\": [\"M150 (line 5) has no configured action: ignored\"]"), std::string::npos);
}

// The runner's log keeps the first ActionRunner::kLogged actions (reserved,
// so the cycle never allocates for it) and counts every one.
TEST(ActionLog, KeepsTheFirstActionsAndCountsThemAll) {
  control::Job job;
  control::CutPath path;
  path.start = {0, 0};
  hal::SegmentCommand seg;
  seg.end = {1, 0};
  seg.feed = 10;
  path.segments.push_back(seg);
  job.paths.push_back(path);
  const std::size_t n = control::ActionRunner::kLogged + 100;
  for (std::size_t k = 0; k < n; ++k) {
    control::JobAction a;
    a.kind = k % 2 == 0 ? CanonKind::tool : CanonKind::dwell;  // dwell 0 s: done at its first poll
    a.index = static_cast<int>(k);
    a.line = k + 1;
    job.actions.push_back(a);
  }
  control::WholeJobSource source(job);
  ASSERT_NE(source.open(0), nullptr);
  control::ActionRunner runner(source, nullptr, -1);
  runner.begin(0, 0.0);
  ASSERT_TRUE(runner.step(0.0, false));
  EXPECT_EQ(runner.log().size(), control::ActionRunner::kLogged);
  EXPECT_EQ(runner.counts().run, n);
  EXPECT_EQ(runner.counts().dwells, n / 2);
  EXPECT_STREQ(runner.log()[2].what, "tool 2");
  EXPECT_EQ(runner.log().back().line, control::ActionRunner::kLogged);
}

}  // namespace
}  // namespace kerf::test
