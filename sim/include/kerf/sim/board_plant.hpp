// sim::BoardPlant: the axes behind the simulated motion board. Each servo
// tick the board's interpolator commands a position; the plant follows it
// through a first-order lag (time constant tau: at a steady speed v the gap is
// about v * tau) and reports where the axes really are, as an encoder would.
// An axis can stall (a jammed carriage, a drive without power): its actual
// position stays put while the command runs on. Thread-safe: the Modbus
// server thread reads actual() while the simulation steps the plant.
#pragma once

#include <array>
#include <mutex>

#include "kerf/geom/vec2.hpp"

namespace kerf::sim {

class BoardPlant {
 public:
  explicit BoardPlant(Vec2<double> start, double tau_s = 0.002);
  // Follows `commanded` for dt_s seconds.
  void step(Vec2<double> commanded, double dt_s);
  // Axis 0 (x) or 1 (y) stops where it is, for good.
  void stall(int axis);
  Vec2<double> actual() const;

 private:
  mutable std::mutex mu_;
  double tau_s_;
  Vec2<double> actual_;
  std::array<bool, 2> stalled_{};
};

}  // namespace kerf::sim
