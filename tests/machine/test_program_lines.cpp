// kerf run's program outputs and inputs: control::GpioOutputs over the
// hal::Gpio program lines ([[gpio.output]], [[gpio.input]]) on the
// simulated board, the outputs going off at the end, at an E-stop and on a
// failed line, and the check at load (machine_can_run) with the key to add.
#include <gtest/gtest.h>

#include "control/job_actions.hpp"
#include "fake_gpio.hpp"
#include "program_fixture.hpp"
#include "simulated/sim_machine.hpp"

namespace kerf::test {
namespace {

using control::State;

struct Lines {
  FakeGpio gpio;
  control::GpioOutputs outputs{gpio};
  control::ControllerConfig cfg = fast();
  Lines() {
    gpio.outputs = {{2, false}, {7, false}};
    gpio.program_inputs = {{1, false}};
    cfg.outputs = &outputs;
  }
  simulated::SimMachineResult run(const control::Job& job) {
    return simulated::run_sim_machine(job, cfg, {}, gpio, nullptr, {});
  }
};

TEST(ProgramLines, OutputsAndInputsRunOnTheLinesAndTheOutputsEndOff) {
  const control::FittedJob f = fitted(two_cuts("M64 P2\nM66 P1 L3 Q5"));
  Lines m;
  m.gpio.at(0.0, [](FakeGpio& g) { g.program_inputs[1] = true; });
  const auto r = m.run(f.job);
  ASSERT_EQ(r.run.state, State::done) << r.run.reason;
  ASSERT_EQ(r.run.actions.size(), 2u);
  EXPECT_NE(std::string(r.run.actions[1].what).find("met"), std::string::npos) << r.run.actions[1].what;
  EXPECT_LT(r.run.actions[1].duration_s, 0.01);  // the input was high: no wait
  ASSERT_EQ(m.gpio.output_changes.size(), 2u);
  EXPECT_EQ(m.gpio.output_changes[0].number, 2);
  EXPECT_TRUE(m.gpio.output_changes[0].on);
  EXPECT_FALSE(m.gpio.output_changes[1].on);  // off at the job's end, after the last cut
  EXPECT_GT(m.gpio.output_changes[1].t, r.run.actions[1].t_s + 1.0);
  EXPECT_FALSE(m.gpio.outputs[2]);
}

TEST(ProgramLines, AnEStopTurnsTheProgramOutputsOff) {
  const control::FittedJob f = fitted(two_cuts("M64 P2\nM64 P7"));
  Lines probe;
  const auto p = probe.run(f.job);
  ASSERT_EQ(p.run.state, State::done) << p.run.reason;
  const double estop_at = p.run.actions.at(0).t_s + 0.5;  // inside the second cut
  Lines m;
  m.gpio.at(estop_at, [](FakeGpio& g) { g.inputs.estop = true; });
  const auto r = m.run(f.job);
  ASSERT_EQ(r.run.state, State::estop) << r.run.reason;
  EXPECT_FALSE(m.gpio.outputs[2]);
  EXPECT_FALSE(m.gpio.outputs[7]);
  ASSERT_EQ(m.gpio.output_changes.size(), 4u);  // 2 and 7 on, then both off at the E-stop
  EXPECT_GE(m.gpio.output_changes[2].t, estop_at);
  EXPECT_LT(m.gpio.output_changes[2].t, estop_at + 0.01);
  EXPECT_FALSE(m.gpio.output_changes[3].on);
}

TEST(ProgramLines, AnOutputThatCannotBeSetIsAFault) {
  const control::FittedJob f = fitted(two_cuts("M64 P2"));
  Lines m;
  m.gpio.fail_outputs = true;
  const auto r = m.run(f.job);
  EXPECT_EQ(r.run.state, State::fault);
  EXPECT_NE(r.run.reason.find("gpio: output 2"), std::string::npos) << r.run.reason;
  EXPECT_EQ(r.run.completed_this_run, 1u);  // the second path never started
}

TEST(ProgramLines, ALoadCheckRefusesAnyLineTheMachineDoesNotHaveWithTheKeyToAdd) {
  control::MachineIo io;
  std::string error;
  job::GcodeProgram out = program(two_cuts("M65 P3"));
  EXPECT_FALSE(control::machine_can_run(out, io, error));
  EXPECT_EQ(error, "t.ngc:6: digital output 3 has no line: add [[gpio.output]] with number = 3 "
                   "(and its offset or name) to the configuration");
  io.outputs = {3};
  EXPECT_TRUE(control::machine_can_run(out, io, error)) << error;
  io.bench = true;
  EXPECT_FALSE(control::machine_can_run(out, io, error));
  EXPECT_EQ(error, "t.ngc:6: digital output 3: a bench ([bench] enabled = true) runs motion only");

  job::GcodeProgram in = program(two_cuts("M66 P4 L0"));
  EXPECT_FALSE(control::machine_can_run(in, io, error));
  EXPECT_EQ(error, "t.ngc:6: input 4 (M66 P4) has no line: add [[gpio.input]] with number = 4 "
                   "(and its offset or name) to the configuration");
  io.inputs = {4};
  EXPECT_TRUE(control::machine_can_run(in, io, error)) << error;
}

TEST(ProgramLines, AnalogNumbersRunOnlyWhenIgnoredAndAreNotedOnce) {
  control::MachineIo io;
  std::string error;
  job::GcodeProgram prog = program(two_cuts("M68 E1 Q2\nM67 E3 Q50\nM66 E2 L0\nM68 E1 Q0"));
  EXPECT_FALSE(control::machine_can_run(prog, io, error));
  EXPECT_EQ(error, "t.ngc:6: analog output 1 (M67/M68 E1): kerf has no analog lines: add 1 to [analog] ignore "
                   "to run the program without it");
  io.analog_ignore = {1};  // E3 is QtPlasmaC's feed %: never asked for
  EXPECT_FALSE(control::machine_can_run(prog, io, error));
  EXPECT_EQ(error, "t.ngc:8: analog input 2 (M66 E2): kerf has no analog lines: add 2 to [analog] ignore "
                   "to run the program without it");
  io.analog_ignore = {2, 1};
  ASSERT_TRUE(control::machine_can_run(prog, io, error)) << error;
  EXPECT_EQ(prog.interp.notes, (std::vector<std::string>{"analog output 1 ignored ([analog] ignore), first at line 6",
                                                          "analog input 2 ignored ([analog] ignore), first at line 8"}));
}

}  // namespace
}  // namespace kerf::test
