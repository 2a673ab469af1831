// kerf's own homing search on a GPIO home switch ([[machine.axis]]
// home_input: a [[gpio.input]] number), for a switch wired to the host rather
// than to the board: jog moves (machine/jog.hpp) watched against the line,
// then the board takes the latch point as the home position (home block
// dir 0, hal/modbus/REGISTERS.md). The board's own search (home_input
// absent) is the better choice: its timing sits next to the switch, while
// here the latch is as exact as the host's poll of the line (a few ms) times
// the latch speed.
#pragma once

#include <string>

#include "kerf/hal/gpio.hpp"
#include "kerf/hal/segment_link.hpp"

namespace kerf::machine {

// Towards the switch at the search speed until the line trips (the search
// distance at most), back by the back-off (and on until off the switch) at
// the search speed, towards it again at the latch speed until it trips; each
// leg ramps to a stop on the path. True with `here`: the home command (dir 0)
// whose home_position makes the latch point h.home_position. False with the
// reason: the switch never tripped within the search distance, the E-stop,
// the line or the link.
bool search_gpio_switch(hal::SegmentLink& link, hal::Gpio& gpio, const hal::HomeCommand& h, int input,
                        hal::HomeCommand& here, std::string& error);

}  // namespace kerf::machine
