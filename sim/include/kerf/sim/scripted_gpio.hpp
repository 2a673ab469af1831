// sim::ScriptedGpio: hal::Gpio for the simulator. It stands in for the plasma
// source and the operator. The source: when the torch turns on, arc-OK
// follows arc_delay_s later (unless the script says the arc never strikes) and
// drops when the torch goes off. The operator and the machine: a script of
// timed events (E-stop, limit switches, lost arcs, hold and cycle-start
// presses) on the same clock the controller passes to read(now_s). The
// values it reports are logical: active-low and debounce belong to the real
// backend, not to this stand-in.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "kerf/hal/gpio.hpp"

namespace kerf::sim {

struct GpioEvent {
  enum class Kind : unsigned char { estop, limit, arc_lost, no_arc, hold, cycle_start, reset };
  double t_s = 0.0;
  Kind kind = Kind::estop;
  bool on = true;           // estop, limit: the level from t_s on
  int limit = -1;           // limit: which one
  double duration_s = 0.0;  // hold, cycle_start, reset: how long the button is down; 0: the default
};

// The script format (sim/README.md): one event per line, `AT_SECONDS EVENT
// [ARGS]`, `#` starts a comment; times never go backwards. The events are
// appended to `out` (after --fault events, say; ScriptedGpio::add sorts them).
// All or nothing: on error `out` is untouched and `error` is "SOURCE:LINE: reason".
bool parse_gpio_script(std::string_view text, const std::string& source, std::size_t limit_count,
                       std::vector<GpioEvent>& out, std::string& error);
bool load_gpio_script(const std::string& path, std::size_t limit_count,
                      std::vector<GpioEvent>& out, std::string& error);
// A fault from the command line, in `kerf sim --fault`'s KIND@SECONDS[:DURATION]
// form: `estop@1.25` (on from then; with :D off again D seconds later),
// `limit-N@T[:D]` likewise, `arc-lost@T`, `no-arc@T`, `hold@T[:D]`,
// `cycle-start@T[:D]`, `reset@T[:D]` (a press of D seconds, default press_s). Appends one or
// two events to `out`; on error appends nothing.
bool parse_gpio_fault(std::string_view spec, std::size_t limit_count,
                      std::vector<GpioEvent>& out, std::string& error);

struct TorchChange {
  double t_s;
  bool on;
  bool operator==(const TorchChange&) const = default;
};

struct ScriptedGpioOptions {
  std::size_t limit_count = 0;  // at most hal::kMaxLimitLines (more are cut)
  double arc_delay_s = 0.05;    // torch on -> arc-OK
  double press_s = 0.1;         // a hold / cycle-start press without a duration
};

class ScriptedGpio final : public hal::Gpio {
 public:
  explicit ScriptedGpio(const ScriptedGpioOptions& options = {});

  // Adds an event (any order: they are kept sorted by time, equal times in the
  // order added). An event whose time has already passed applies at the next
  // read. False with `error` for a limit index out of range or a bad time.
  bool add(const GpioEvent& e, std::string& error);
  bool add(const std::vector<GpioEvent>& events, std::string& error);
  // Shorthands for tests; they fail (return false) only where add() would.
  bool estop_at(double t_s, bool on);
  bool limit_at(double t_s, int limit, bool on);
  bool arc_lost_at(double t_s);
  bool no_arc_at(double t_s);
  bool hold_at(double t_s, double duration_s = 0.0);
  bool cycle_start_at(double t_s, double duration_s = 0.0);
  bool reset_at(double t_s, double duration_s = 0.0);
  // Whether the script presses reset at all (the machine then has a reset button).
  bool has_reset() const;

  // Fault hooks: from this time on read() / set_torch() fail as an I/O error would.
  void fail_reads_from(double t_s) { fail_reads_from_ = t_s; }
  void fail_torch_from(double t_s) { fail_torch_from_ = t_s; }

  // Applies every event up to now_s, then reports the inputs at now_s.
  bool read(double now_s, hal::GpioInputs& in) override;
  // Takes effect at the time of the last read() (0 before the first): the
  // controller reads, decides, then drives, all in one cycle.
  bool set_torch(bool on) override;
  // The watchdog output: its changes are counted, the last one timed.
  bool set_watchdog(bool level) override;
  std::uint64_t watchdog_changes() const { return watchdog_changes_; }
  double watchdog_last_change_s() const { return watchdog_last_s_; }
  // The thc_lock output: every change, at the time it took effect.
  bool set_thc_lock(bool on) override;
  bool thc_lock() const { return thc_lock_; }
  const std::vector<TorchChange>& thc_lock_timeline() const { return thc_lock_timeline_; }
  const char* last_error() const override { return error_.c_str(); }

  // Every change of the torch output, in order, at the time it took effect.
  const std::vector<TorchChange>& torch_timeline() const { return timeline_; }
  bool torch() const { return torch_; }
  double last_read_s() const { return now_s_; }

 private:
  void apply(const GpioEvent& e);

  ScriptedGpioOptions options_;
  std::vector<GpioEvent> events_;
  std::size_t next_ = 0;  // first event not applied yet
  double now_s_ = 0.0;

  bool torch_ = false;
  double torch_on_s_ = 0.0;
  bool no_arc_armed_ = false;  // the next torch-on never gets arc-OK
  bool arc_denied_ = false;    // this torch-on never gets arc-OK
  bool arc_lost_ = false;

  bool estop_ = false;
  std::array<bool, hal::kMaxLimitLines> limits_{};
  double hold_from_ = 0.0, hold_until_ = 0.0;
  double cycle_from_ = 0.0, cycle_until_ = 0.0;
  double reset_from_ = 0.0, reset_until_ = 0.0;
  bool watchdog_ = false;
  std::uint64_t watchdog_changes_ = 0;
  double watchdog_last_s_ = -1.0;

  double fail_reads_from_;
  double fail_torch_from_;
  std::vector<TorchChange> timeline_;
  bool thc_lock_ = false;
  std::vector<TorchChange> thc_lock_timeline_;
  std::string error_;
};

}  // namespace kerf::sim
