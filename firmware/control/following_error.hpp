// control::FollowingError: the gap between where the axes were told to be
// (BoardStatus::position) and where they are (BoardStatus::actual), checked
// per axis against LinuxCNC's FERROR/MIN_FERROR rule: the limit is ferror at
// the axis's full speed and shrinks linearly with its speed down to
// min_ferror at rest,
//   limit = min_ferror + (ferror - min_ferror) * |v| / v_max.
// The axis speed is the commanded position's change between two statuses,
// held at its peak for kSpeedHoldS: a status that repeats the last one (the
// link has not moved on yet) does not drop the limit to min_ferror.
#pragma once

#include "kerf/geom/vec2.hpp"

namespace kerf::control {

struct FerrorLimits {
  double ferror_mm = 1.0;          // at v_max
  double min_ferror_mm = 0.25;     // at rest
  double max_speed_mm_s = 10000.0 / 60.0;
};

double ferror_limit(const FerrorLimits& l, double speed_mm_s);

struct FerrorVerdict {
  bool over = false;
  int axis = 0;            // 0 x, 1 y: the worst axis (the first over, if any)
  double error_mm = 0.0;   // |actual - commanded| on that axis
  double limit_mm = 0.0;
  double speed_mm_s = 0.0;
};

class FollowingError {
 public:
  explicit FollowingError(const FerrorLimits& l = {}) : limits_(l) {}
  // One fresh status at controller time now_s.
  FerrorVerdict check(Vec2<double> commanded, Vec2<double> actual, double now_s);
  // The next status starts a new speed estimate.
  void forget() {
    have_prev_ = false;
    held_speed_[0] = held_speed_[1] = 0.0;
  }
  double max_error_mm() const { return max_error_; }

 private:
  FerrorLimits limits_;
  bool have_prev_ = false;
  Vec2<double> prev_{};
  double prev_t_ = 0.0;
  double max_error_ = 0.0;
  double held_speed_[2] = {0.0, 0.0};
  double held_t_[2] = {0.0, 0.0};
};

inline constexpr double kSpeedHoldS = 0.02;

}  // namespace kerf::control
