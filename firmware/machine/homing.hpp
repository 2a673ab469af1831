// `kerf home`'s session: each axis homed in turn by the board (Modbus: the
// home block and command 7) or the drive (CiA 402 homing mode), the host
// following it through the status and watching the E-stop line, which
// aborts the cycle (the axis stays unhomed). The result goes into the
// machine state file (homed axes, the position), so a later `kerf run`
// finds it.
#pragma once

#include <cstdio>
#include <string>

#include "config/config.hpp"
#include "job/machine_state.hpp"
#include "kerf/hal/gpio.hpp"
#include "kerf/hal/segment_link.hpp"

namespace kerf::machine {

// The homing parameters of axis a (0 x, 1 y, 2 z) from the configuration.
hal::HomeCommand home_command(const config::Machine& m, int axis);

// Homes the axes in `axes` (bit 0 x, bit 1 y, bit 2 z) that the machine
// has, z first (the torch up, clear of the sheet), then x, then y. Marks each homed axis in `state` and records the position. False
// with the reason ("x: the switch never tripped within the search distance
// (2000 mm)", "E-stop", a link error) at the first axis that fails; the
// axes homed before it stay homed.
bool home_axes(const config::Config& cfg, unsigned axes, hal::SegmentLink& link, hal::Gpio* gpio,
               job::MachineState& state, std::string& error, std::FILE* log);

// kerf run's rule (before anything moves): every axis of the machine (z
// too, when it has one) homed in the state file, or the machine has no switches and the operator said --assume-homed.
// False with the reason.
bool check_homed(const config::Config& cfg, const job::MachineState& state, bool assume_homed, std::string& error);

// kerf run's second check, once the link is up: the board (Modbus status
// register 22) or the drives (CiA 402 homing attained, read at bring-up) must
// say homed too for every axis the state file says is. A board that was
// power-cycled since `kerf home` lost its home: false with the reason.
bool check_board_homed(const job::MachineState& state, hal::SegmentLink& link, std::string& error);

}  // namespace kerf::machine
