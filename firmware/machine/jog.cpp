#include "machine/jog.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace kerf::machine {

namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The operator let go: ramp to a stop on the path, then drop the rest of
// the move and leave the board idle where it stands.
bool stop_released(hal::SegmentLink& link, hal::BoardStatus& st, Vec2<double>& at, std::string& error) {
  if (link.command(hal::Command::hold) != hal::LinkError::none) {
    link.command(hal::Command::abort);
    error = std::string("hold: ") + link.last_error();
    return false;
  }
  Vec2<double> last{1e300, 1e300};
  const double t0 = now_s();
  for (int still = 0; still < 3 && now_s() - t0 < 10.0;) {  // three polls without motion: at rest
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (link.status(st) != hal::LinkError::none) break;
    still = st.position.x == last.x && st.position.y == last.y ? still + 1 : 0;
    last = st.position;
    if (st.state == hal::BoardState::done || st.state == hal::BoardState::fault) break;
  }
  link.command(hal::Command::abort);  // drops the rest of the move
  link.status(st);
  at = st.position;
  // abort faults the board; the reset is taken once the axes are at rest.
  for (int i = 0; i < 200 && st.state == hal::BoardState::fault; ++i) {
    link.command(hal::Command::fault_reset);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (link.status(st) != hal::LinkError::none) break;
  }
  at = st.position;
  if (st.state == hal::BoardState::fault) {
    error = "released, but the board stayed in fault (faults 0x" + std::to_string(st.faults) + ")";
    return false;
  }
  return true;
}

bool jog(hal::SegmentLink& link, hal::Gpio* gpio, Vec2<double> to, double feed, const std::function<bool()>& released,
         Vec2<double>& at, std::string& error, Vec2<double>* released_at) {
  hal::BoardStatus st;
  auto link_error = [&](const char* what) {
    error = std::string(what) + ": " + link.last_error();
    return false;
  };
  if (link.status(st) != hal::LinkError::none) return link_error("cannot read the board");
  at = st.position;
  if (st.state == hal::BoardState::fault && link.command(hal::Command::fault_reset) != hal::LinkError::none)
    return link_error("the board is in fault and refused the reset");
  if (std::hypot(to.x - at.x, to.y - at.y) < 0.001) return true;  // there already (within a count)
  hal::SegmentCommand seg;
  seg.seq = st.last_accepted + 1;
  seg.kind = SegmentKind::line;
  seg.end = to;
  seg.feed = feed;
  seg.torch = false;
  if (link.command(hal::Command::start) != hal::LinkError::none) return link_error("start");
  if (link.push(seg, st) != hal::LinkError::none) return link_error("jog segment");
  if (link.command(hal::Command::finish) != hal::LinkError::none) return link_error("finish");
  const double t0 = now_s();
  const double limit = std::hypot(to.x - at.x, to.y - at.y) / feed + 10.0;
  for (;;) {
    hal::GpioInputs in;
    if (gpio != nullptr && (!gpio->read(now_s() - t0, in) || in.estop)) {
      link.command(hal::Command::abort);
      link.status(st);
      at = st.position;
      error = "E-stop: the jog stopped";
      return false;
    }
    if (link.status(st) != hal::LinkError::none) {
      link.command(hal::Command::abort);
      return link_error("lost the board while jogging");
    }
    at = st.position;
    if (st.state == hal::BoardState::done) return true;
    if (released && released()) {
      if (released_at != nullptr) *released_at = st.position;
      return stop_released(link, st, at, error);
    }
    if (st.state == hal::BoardState::fault) {
      error = "the board faulted while jogging (faults 0x" + std::to_string(st.faults) + ")";
      return false;
    }
    if (now_s() - t0 > limit) {
      link.command(hal::Command::abort);
      error = "the jog did not end in time";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace

bool jog_to(hal::SegmentLink& link, hal::Gpio* gpio, Vec2<double> to, double feed, Vec2<double>& at,
            std::string& error) {
  return jog(link, gpio, to, feed, {}, at, error, nullptr);
}

bool jog_until_released(hal::SegmentLink& link, hal::Gpio* gpio, Vec2<double> to, double feed,
                        const std::function<bool()>& released, Vec2<double>& at, std::string& error,
                        Vec2<double>* released_at) {
  return jog(link, gpio, to, feed, released, at, error, released_at);
}

bool continuous_target(Vec2<double> from, int axis, int dir, const motion::SoftLimits<double>& limits,
                       Vec2<double>& to) {
  if (!limits.on[axis]) return false;
  to = from;
  (axis == 0 ? to.x : to.y) = dir > 0 ? limits.max[axis] : limits.min[axis];
  return true;
}

bool clamp_to_limits(Vec2<double>& to, const motion::SoftLimits<double>& limits) {
  bool clamped = false;
  double* v[2] = {&to.x, &to.y};
  for (int a = 0; a < 2; ++a) {
    if (!limits.on[a]) continue;
    const double c = std::clamp(*v[a], limits.min[a], limits.max[a]);
    clamped = clamped || c != *v[a];
    *v[a] = c;
  }
  return clamped;
}

void touch_off(job::MachineState& s, Vec2<double> machine) {
  s.g5x[s.coord][0] = machine.x - (s.g92_on ? s.g92[0] : 0.0);
  s.g5x[s.coord][1] = machine.y - (s.g92_on ? s.g92[1] : 0.0);
}

}  // namespace kerf::machine
