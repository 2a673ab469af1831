// `kerf jog` and `kerf touch-off`: short sessions over the configured link.
// A jog (incremental, or continuous until released) is one travel line (torch off) to a target at the jog speed, streamed
// like a job's segment; the E-stop line aborts it (the board stops on the
// path). Touch-off sets the active work offset so that where the axes stand
// becomes X0 Y0, as G10 L20 P0 X0 Y0 does, and keeps it in the state file.
#pragma once

#include <cstdio>
#include <functional>
#include <string>

#include "config/config.hpp"
#include "job/machine_state.hpp"
#include "kerf/geom/vec2.hpp"
#include "kerf/hal/gpio.hpp"
#include "kerf/hal/segment_link.hpp"
#include "kerf/motion/soft_limits.hpp"

namespace kerf::machine {

// Moves the axes to `to` (mm, machine position) at `feed` mm/s. True when it
// got there; false with the reason (E-stop, a board fault, the link).
// `at` is where the axes stopped.
bool jog_to(hal::SegmentLink& link, hal::Gpio* gpio, Vec2<double> to, double feed, Vec2<double>& at,
            std::string& error);

// A continuous jog (jog until released): towards `to` (the soft limit in the
// jog's direction) at `feed` mm/s until `released()` holds (the operator let
// go), the limit is reached, or a fault. Released: the board ramps to a stop
// on the path (feed hold), then the rest of the move is dropped (abort, fault
// reset), as grblHAL's jog cancel (0x85) does; true, `at` where it stopped.
// The E-stop line and a board fault: false with the reason, as jog_to.
// `released_at`: where the axes were at the poll that saw the release.
bool jog_until_released(hal::SegmentLink& link, hal::Gpio* gpio, Vec2<double> to, double feed,
                        const std::function<bool()>& released, Vec2<double>& at, std::string& error,
                        Vec2<double>* released_at = nullptr);

// The target of a continuous jog: the soft limit of `axis` (0 x, 1 y) in
// direction `dir` (+1, -1) from `from`. False when that axis has no limits:
// a continuous jog must end somewhere.
bool continuous_target(Vec2<double> from, int axis, int dir, const motion::SoftLimits<double>& limits,
                       Vec2<double>& to);

// A jog stops at the soft limits: `to` is brought inside them. True when it
// was outside (the jog then ends at the limit).
bool clamp_to_limits(Vec2<double>& to, const motion::SoftLimits<double>& limits);

// G10 L20 on the active system: the offset that makes `machine` read X0 Y0
// (the G92 offset, when applied, counts as G10 L20 counts it).
void touch_off(job::MachineState& s, Vec2<double> machine);

}  // namespace kerf::machine
