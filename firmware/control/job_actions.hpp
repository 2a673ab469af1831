// The actions a job runs between its paths, at rest with the torch off
// (control/job.hpp JobAction): G4 dwell, M0/M1 pause until cycle-start,
// M62..M65 and M7/M8/M9 digital outputs, M67/M68 analog outputs, M66 wait on
// an input with a timeout, and the recorded ones (tool change, end).
//
// M66 modes (LinuxCNC's L): L0 reads the input and goes on; L1 waits for a
// rising edge, L2 for a falling edge, L3 for high, L4 for low, each at most
// Q seconds. As in LinuxCNC a timeout is not a fault: the wait ends, the
// program goes on, and the log says "timed out".
//
// Outputs "synchronised with motion" (M62/M63/M67) and "immediate"
// (M64/M65/M68) both switch here, before the next move starts: between
// paths the machine is at rest, so the two are the same instant.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "control/job.hpp"

namespace kerf::control {

// The machine's program outputs and inputs (beyond the torch, on hal::Gpio).
class Outputs {
 public:
  virtual ~Outputs() = default;
  virtual void set_digital(int index, bool on) = 0;
  virtual void set_analog(int index, double value) = 0;
  virtual bool digital_input(int index) = 0;
};

// What the simulator and the tests use: remembers outputs; inputs are the
// values set in `inputs` (false when absent).
class MemoryOutputs : public Outputs {
 public:
  void set_digital(int index, bool on) override;
  void set_analog(int index, double value) override;
  bool digital_input(int index) override;
  std::vector<std::pair<int, bool>> digital;   // every switch, in order
  std::vector<std::pair<int, double>> analog;
  std::vector<bool> inputs;
};

struct ActionEvent {
  double t_s = 0;        // controller time it started
  double duration_s = 0; // how long it held the machine
  std::size_t line = 0;  // source line
  job::CanonKind kind = job::CanonKind::dwell;
  std::string what;      // "dwell 0.5 s", "pause (M0): cycle-start", "M66 P0 L3: timed out" ...
  Vec2<double> at{};
};

class ActionRunner {
 public:
  // operator_delay_s >= 0: a simulated operator presses cycle-start that
  // long after a pause starts; < 0: the real button.
  ActionRunner(const Job& job, Outputs* outputs, double operator_delay_s)
      : job_(job), outputs_(outputs), operator_delay_s_(operator_delay_s) {}

  // The actions before paths[path] (path == size: after the last) are next.
  void begin(std::size_t path, double now_s);
  // Applies the outputs of every action before paths[path] without running
  // the rest (a resumed run: dwells, pauses and waits before the resume point are skipped).
  void replay_outputs(std::size_t path);
  bool pending() const { return next_ < end_; }
  bool paused() const { return waiting_ && job_.actions[next_].kind == job::CanonKind::pause; }
  // One cycle: runs what can run now; true once every pending action is done.
  bool step(double now_s, bool cycle_start_pressed);
  const std::vector<ActionEvent>& log() const { return log_; }

 private:
  bool start(const JobAction& a, double now_s);  // true: done at once
  bool poll(const JobAction& a, double now_s, bool cycle_start_pressed);
  void done(double now_s, const std::string& what);

  const Job& job_;
  Outputs* outputs_;
  double operator_delay_s_;
  std::size_t next_ = 0, end_ = 0;
  bool waiting_ = false, last_input_ = false;
  double started_ = 0;
  std::vector<ActionEvent> log_;
};

}  // namespace kerf::control
