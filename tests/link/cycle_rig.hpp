// A whole job through the real controller and the simulated board over
// loopback Modbus, stepped by hand (the test thread runs every cycle), with
// lines that allocate nothing, so that the cycle's own allocations can be
// counted. The job has three paths with z moves before and after each, lines
// and an arc, a pierce each.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <thread>
#include <memory>
#include <string>

#include "control/controller.hpp"
#include "simulated/sim_machine.hpp"
#include "simulated/sim_plant.hpp"

namespace kerf::test {

// Arc-OK 20 ms after the torch comes on; counts torch changes; no heap.
class QuietGpio final : public hal::Gpio {
 public:
  bool read(double now_s, hal::GpioInputs& in) override {
    now_ = now_s;
    in = hal::GpioInputs{};
    in.arc_ok = torch_ && now_s >= torch_on_t_ + 0.02;
    return true;
  }
  bool set_torch(bool on) override {
    if (on && !torch_) {
      torch_on_t_ = now_;
      ++torch_ons;
    }
    torch_ = on;
    return true;
  }
  const char* last_error() const override { return ""; }
  bool torch() const { return torch_; }
  int torch_ons = 0;

 private:
  double now_ = 0, torch_on_t_ = 0;
  bool torch_ = false;
};

inline hal::SegmentCommand line_seg(Vec2<double> end, double feed = 60.0) {
  hal::SegmentCommand s;
  s.kind = SegmentKind::line;
  s.end = end;
  s.feed = feed;
  return s;
}

inline hal::SegmentCommand z_seg(double z) {
  hal::SegmentCommand s;
  s.z_move = true;
  s.z = z;
  s.feed = 40.0;
  return s;
}

// Three small squares-ish paths (one with an arc), z down before, up after.
inline control::Job z_job() {
  control::Job job;
  for (int p = 0; p < 3; ++p) {
    const double x = 20.0 * p;
    control::CutPath c;
    c.start = {x, 0};
    c.before = {z_seg(5.0), z_seg(1.5)};
    c.segments = {line_seg({x + 6, 0}), line_seg({x + 6, 6}), line_seg({x, 6}), line_seg({x, 0})};
    if (p == 1) {
      hal::SegmentCommand arc = line_seg({x + 6, 0});
      arc.kind = SegmentKind::arc;
      arc.centre = {x + 3, 0};
      arc.dir = 1;
      c.segments[0] = arc;
    }
    c.after = {z_seg(10.0)};
    c.pierce_delay_s = 0.05;
    job.paths.push_back(c);
  }
  return job;
}

inline simulated::SimMachineConfig z_machine() {
  simulated::SimMachineConfig m;
  m.cycle_s = 0.002;
  m.z = {m.motion.servo_period_s, 50.0, 1000.0};
  return m;
}

inline control::ControllerConfig quick_controller() {
  control::ControllerConfig c;
  c.rapid_feed_mm_s = 200.0;
  c.pierce_delay_s = 0.05;
  c.arc_ok_timeout_s = 0.5;
  return c;
}

struct CycleRig {
  control::Job job = z_job();
  simulated::SimMachineConfig machine = z_machine();
  QuietGpio gpio;
  std::unique_ptr<simulated::SimPlant> plant;
  std::unique_ptr<control::Controller> ctl;
  double t = 0;
  bool pace_journal = true;  // as the simulator: simulated time waits while the journal writer lags

  // source: the job to run instead of z_job() (a streamed one).
  CycleRig(const control::ControllerConfig& cfg, control::Journal* journal, control::JobSource* source = nullptr) {
    std::string err;
    plant = simulated::make_modbus_plant(machine, cfg.link_watchdog_s, err);
    if (!plant) throw std::runtime_error("plant: " + err);
    ctl = source ? std::make_unique<control::Controller>(*source, cfg, plant->link(), gpio, journal)
                 : std::make_unique<control::Controller>(job, cfg, plant->link(), gpio, journal);
  }
  // Cycles until finished (or max_s of simulated time); around each
  // Controller::cycle call `around(true)` before and `around(false)` after.
  // `each` runs between cycles.
  bool run(double max_s, const std::function<void(bool)>& around = {},
           const std::function<void()>& each = {}) {
    const long ticks = std::lround(machine.cycle_s / plant->tick_s());
    while (!ctl->finished() && t < max_s) {
      while (pace_journal && ctl->journal_lagging()) std::this_thread::sleep_for(std::chrono::microseconds(100));
      if (around) around(true);
      ctl->cycle(t);
      if (around) around(false);
      for (long i = 0; i < ticks; ++i) plant->tick();
      t += machine.cycle_s;
      if (each) each();
    }
    return ctl->finished();
  }
};

}  // namespace kerf::test
