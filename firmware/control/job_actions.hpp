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
#include "control/job_source.hpp"
#include "kerf/hal/gpio.hpp"

namespace kerf::control {

// The machine's program outputs and inputs (beyond the torch). Each call
// returns false on an I/O error (last_error says which line): the
// controller makes that a fault, as for the torch.
class Outputs {
 public:
  virtual ~Outputs() = default;
  virtual bool set_digital(int index, bool on) = 0;
  virtual bool set_analog(int index, double value) = 0;
  // Reads input `index` at `now_s` (debounced on a real machine) into `value`.
  virtual bool digital_input(int index, double now_s, bool& value) = 0;
  // Every digital output off: a fault, an E-stop, the job's end.
  virtual bool all_off() = 0;
  virtual const char* last_error() const { return ""; }
};

// What the simulator and the tests use: remembers outputs; inputs are the
// values set in `inputs` (false when absent).
class MemoryOutputs : public Outputs {
 public:
  bool set_digital(int index, bool on) override;
  bool set_analog(int index, double value) override;
  bool digital_input(int index, double now_s, bool& value) override;
  bool all_off() override;
  std::vector<std::pair<int, bool>> digital;   // every switch, in order
  std::vector<std::pair<int, double>> analog;
  std::vector<bool> inputs;
  int all_off_calls = 0;                        // all_off() does not add to `digital`
};

// kerf run's: the program lines of hal::Gpio ([[gpio.output]],
// [[gpio.input]]). Analog numbers have no line: the ones the job uses were
// checked at load against [analog] ignore (program_job.hpp), so set_analog
// drives nothing.
class GpioOutputs : public Outputs {
 public:
  explicit GpioOutputs(hal::Gpio& gpio) : gpio_(gpio) {}
  bool set_digital(int index, bool on) override { return gpio_.set_output(index, on); }
  bool set_analog(int, double) override { return true; }
  bool digital_input(int index, double now_s, bool& value) override { return gpio_.read_input(index, now_s, value); }
  bool all_off() override { return gpio_.outputs_off(); }
  const char* last_error() const override { return gpio_.last_error(); }

 private:
  hal::Gpio& gpio_;
};

// One action run. Plain data with its text in place: the cycle logs it
// without allocating.
struct ActionEvent {
  double t_s = 0;        // controller time it started
  double duration_s = 0; // how long it held the machine
  std::size_t line = 0;  // source line
  job::CanonKind kind = job::CanonKind::dwell;
  char what[96] = {};    // "dwell 0.5 s", "pause (M0): cycle-start", "M66 P0 L3: timed out" ...
  Vec2<double> at{};
};

// What the actions run add up to, whatever the log kept.
struct ActionCounts {
  std::size_t run = 0, dwells = 0, pauses = 0;
};

class ActionRunner {
 public:
  // The log keeps the first kLogged actions run (reserved here, so that the
  // cycle never allocates for it); counts() goes on past them.
  static constexpr std::size_t kLogged = 1024;
  // operator_delay_s >= 0: a simulated operator presses cycle-start that
  // long after a pause starts; < 0: the real button.
  ActionRunner(JobSource& job, Outputs* outputs, double operator_delay_s)
      : job_(job), outputs_(outputs), operator_delay_s_(operator_delay_s) {
    log_.reserve(kLogged);
    error_.reserve(256);
  }

  // The actions before paths[path] (path == size: after the last) are next.
  void begin(std::size_t path, double now_s);
  // Applies the outputs of every action before paths[path] without running
  // the rest (a resumed run: dwells, pauses and waits before the resume point are skipped).
  // False when an output could not be set (error()).
  bool replay_outputs(std::size_t path);
  bool pending() const { return next_ < end_; }
  bool paused() const { return waiting_ && paused_; }
  // One cycle: runs what can run now; true once every pending action is done.
  bool step(double now_s, bool cycle_start_pressed);
  const std::vector<ActionEvent>& log() const { return log_; }
  const ActionCounts& counts() const { return counts_; }
  // The first output or input that failed ("gpio: output 3: ..."); empty while all is well.
  const std::string& error() const { return error_; }

 private:
  bool set_digital(int index, bool on);
  bool set_analog(int index, double value);
  bool input(int index, double now_s);  // false on error too (error_ says so)
  bool failed();                        // keeps the outputs' first error; false
  bool start(const JobAction& a, double now_s);  // true: done at once
  bool poll(const JobAction& a, double now_s, bool cycle_start_pressed);
  __attribute__((format(printf, 3, 4))) void done(double now_s, const char* fmt, ...);

  JobSource& job_;
  Outputs* outputs_;
  double operator_delay_s_;
  std::size_t next_ = 0, end_ = 0;
  bool waiting_ = false, last_input_ = false, paused_ = false;
  double started_ = 0;
  std::vector<ActionEvent> log_;
  ActionCounts counts_;
  std::string error_;
};

}  // namespace kerf::control
