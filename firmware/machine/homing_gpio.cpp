#include "machine/homing_gpio.hpp"

#include <chrono>
#include <cmath>

#include "machine/jog.hpp"

namespace kerf::machine {

namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double along(Vec2<double> p, int a) { return a == 0 ? p.x : p.y; }

Vec2<double> moved(Vec2<double> p, int a, double d) {
  (a == 0 ? p.x : p.y) += d;
  return p;
}

}  // namespace

bool search_gpio_switch(hal::SegmentLink& link, hal::Gpio& gpio, const hal::HomeCommand& h, int input,
                        hal::HomeCommand& here, std::string& error) {
  const int a = h.axis;
  if (a < 0 || a > 1) {
    error = "a GPIO home switch homes x or y";
    return false;
  }
  const double t0 = now_s();
  bool read_failed = false;
  auto on = [&] {  // a line that cannot be read stops the move
    bool v = false;
    if (!gpio.read_input(input, now_s() - t0, v)) read_failed = true;
    return v || read_failed;
  };
  auto off = [&] { return !on(); };
  auto line_error = [&] {
    error = "home_input " + std::to_string(input) + ": " + gpio.last_error();
    return false;
  };
  hal::BoardStatus st;
  if (link.status(st) != hal::LinkError::none) {
    error = std::string("cannot read the board: ") + link.last_error();
    return false;
  }
  const double dir = h.dir < 0 ? -1.0 : 1.0;
  Vec2<double> at = st.position, first = st.position, seen{};
  if (!on()) {  // the search
    if (!jog_until_released(link, &gpio, moved(at, a, dir * h.search_distance), h.search_speed, on, at, error, &first))
      return false;
    if (read_failed) return line_error();
    if (!on()) {
      error = std::string(hal::to_string(hal::HomingState::no_switch)) + " (" + std::to_string(h.search_distance) +
              " mm, GPIO input " + std::to_string(input) + ")";
      return false;
    }
  }
  // Back off, and on until off the switch.
  if (h.backoff > 0 && !jog_to(link, &gpio, moved(at, a, -dir * h.backoff), h.search_speed, at, error)) return false;
  if (on() && !jog_until_released(link, &gpio, moved(at, a, -dir * h.search_distance), h.search_speed, off, at, error))
    return false;
  if (read_failed) return line_error();
  if (on()) {
    error = "the switch did not release within the search distance";
    return false;
  }
  // The latch: up to the back-off past where the search first saw the switch.
  const double reach = std::fabs(along(first, a) - along(at, a)) + h.backoff + 1.0;
  if (!jog_until_released(link, &gpio, moved(at, a, dir * reach), h.latch_speed, on, at, error, &seen)) return false;
  if (read_failed) return line_error();
  if (!on()) {
    error = "the switch did not trip again at the latch speed";
    return false;
  }
  here = h;
  here.dir = 0;
  here.search_distance = 0;
  here.home_position = h.home_position + (along(at, a) - along(seen, a));
  return true;
}

}  // namespace kerf::machine
