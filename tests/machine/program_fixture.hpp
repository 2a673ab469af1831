// G-code programs as controller jobs for the machine tests: through the
// interpreter and the program builder, as kerf sim's and kerf run's.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "control/machine_config.hpp"
#include "control/program_job.hpp"

namespace kerf::test {

inline job::GcodeProgram program(const std::string& gcode) {
  const job::GcodeFile g = job::parse_gcode(gcode, "t.ngc");
  job::Interpretation it;
  job::GcodeProgram prog;
  std::string error;
  const job::InterpSettings s;
  EXPECT_TRUE(job::interpret(g, s, {}, it, error)) << error;
  EXPECT_TRUE(job::build_program(g, s, it, prog, error)) << error;
  return prog;
}

inline control::FittedJob fitted(const std::string& gcode) {
  control::FittedJob out;
  EXPECT_EQ(control::fit_program_or_say(program(gcode), job::Criterion::band, 0.01, 50.0, 200.0, out), 0);
  return out;
}

inline control::ControllerConfig fast() {
  control::ControllerConfig c;
  c.pierce_delay_s = 0.1;
  c.arc_ok_timeout_s = 0.5;
  c.rapid_feed_mm_s = 200.0;
  return c;
}

// Two cuts with `between` in between them.
inline std::string two_cuts(const std::string& between) {
  return "G21 G90\nG0 X0 Y0\nM3\nG1 X20 F1200\nM5\n" + between + "\nG0 X0 Y10\nM3\nG1 X20\nM5\n";
}

}  // namespace kerf::test
