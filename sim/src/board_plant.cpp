#include "kerf/sim/board_plant.hpp"

#include <cmath>

namespace kerf::sim {

BoardPlant::BoardPlant(Vec2<double> start, double tau_s) : tau_s_(tau_s), actual_(start) {}

void BoardPlant::step(Vec2<double> commanded, double dt_s) {
  // The exact step response of the lag over dt: no overshoot at any dt.
  const double k = tau_s_ > 0.0 ? 1.0 - std::exp(-dt_s / tau_s_) : 1.0;
  std::lock_guard<std::mutex> lock(mu_);
  if (!stalled_[0]) actual_.x += k * (commanded.x - actual_.x);
  if (!stalled_[1]) actual_.y += k * (commanded.y - actual_.y);
}

void BoardPlant::stall(int axis) {
  std::lock_guard<std::mutex> lock(mu_);
  if (axis == 0 || axis == 1) stalled_[static_cast<std::size_t>(axis)] = true;
}

Vec2<double> BoardPlant::actual() const {
  std::lock_guard<std::mutex> lock(mu_);
  return actual_;
}

}  // namespace kerf::sim
