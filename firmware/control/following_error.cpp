#include "control/following_error.hpp"

#include <algorithm>
#include <cmath>

namespace kerf::control {

double ferror_limit(const FerrorLimits& l, double speed_mm_s) {
  const double ratio = l.max_speed_mm_s > 0.0 ? std::min(1.0, std::fabs(speed_mm_s) / l.max_speed_mm_s) : 1.0;
  return l.min_ferror_mm + (l.ferror_mm - l.min_ferror_mm) * ratio;
}

FerrorVerdict FollowingError::check(Vec2<double> commanded, Vec2<double> actual, double now_s) {
  const double dt = now_s - prev_t_;
  const double cmd[2] = {commanded.x, commanded.y}, act[2] = {actual.x, actual.y};
  const double was[2] = {prev_.x, prev_.y};
  FerrorVerdict worst;
  double worst_share = -1.0;
  for (int a = 0; a < 2; ++a) {
    double speed = have_prev_ && dt > 0.0 ? std::fabs(cmd[a] - was[a]) / dt : 0.0;
    const auto i = static_cast<std::size_t>(a);
    if (speed >= held_speed_[i] || now_s - held_t_[i] > kSpeedHoldS) {
      held_speed_[i] = speed;
      held_t_[i] = now_s;
    }
    speed = held_speed_[i];
    FerrorVerdict v;
    v.axis = a;
    v.error_mm = std::fabs(act[a] - cmd[a]);
    v.speed_mm_s = speed;
    v.limit_mm = ferror_limit(limits_, speed);
    v.over = v.error_mm > v.limit_mm;
    max_error_ = std::max(max_error_, v.error_mm);
    const double share = v.error_mm / v.limit_mm;
    if (share > worst_share) {
      worst_share = share;
      worst = v;
    }
  }
  prev_ = commanded;
  prev_t_ = now_s;
  have_prev_ = true;
  return worst;
}

}  // namespace kerf::control
