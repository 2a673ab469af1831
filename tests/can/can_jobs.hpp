// The controller job the CAN machine tests run (the Modbus machine tests' job).
#pragma once

#include "../machine/fake_gpio.hpp"
#include "control/job.hpp"
#include "control/controller.hpp"

namespace kerf::test {

// Two paths: an L of two lines, then a half circle of radius 10 and a line.
inline control::Job two_paths() {
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

inline control::ControllerConfig fast_cut() {
  control::ControllerConfig c;
  c.pierce_delay_s = 0.1;
  c.arc_ok_timeout_s = 0.5;
  c.rapid_feed_mm_s = 200.0;
  return c;
}

}  // namespace kerf::test
