// The interpreter settings the G-code goldens (tests/interp) and the G-code
// fuzz target run with: a material on T1, user M-codes M101..M103, the torch
// on output 0, gas on 1 and 2.
#pragma once

#include "job/gcode_interp.hpp"

namespace kerf_test {

inline kerf::job::InterpSettings interp_case_settings() {
  using kerf::job::UserMcode;
  kerf::job::InterpSettings s;
  s.fit_tol = 0.025;
  s.tool_material[1] = {"mild", 2000, 0.2};
  s.mcodes[101] = {UserMcode::Action::on, 3, 0};
  s.mcodes[102] = {UserMcode::Action::dwell, 0, 0.25};
  s.mcodes[103] = {UserMcode::Action::ignore, 0, 0};
  s.torch_output = 0;
  s.mist_output = 1;
  s.flood_output = 2;
  s.max_blocks = 100000;  // the loop cap, low so that a runaway loop is refused in milliseconds
  return s;
}

}  // namespace kerf_test
