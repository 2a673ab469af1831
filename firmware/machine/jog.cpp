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

}  // namespace

bool jog_to(hal::SegmentLink& link, hal::Gpio* gpio, Vec2<double> to, double feed, Vec2<double>& at,
            std::string& error) {
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
