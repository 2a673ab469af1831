// hal::Gpio: the machine's discrete I/O. The outputs: the torch and an
// optional watchdog (a charge pump for an external safety relay: it toggles
// every cycle while all is well). The inputs the controller watches every
// cycle: arc-OK from the plasma source, E-stop, limit switches, the
// operator's feed-hold, cycle-start and reset buttons. Values here are logical (true = asserted): active-low wiring and
// debouncing are the backend's business, configured per line.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace kerf::hal {

// Where one line is and how to read it. A line is given by chip and offset,
// or by its name (the kernel's line label, searched on every chip, or on
// `chip` when that is set too).
struct GpioLineConfig {
  bool used = false;        // false: the machine has no such line
  std::string chip;         // "gpiochip0", "/dev/gpiochip0", or a chip label
  int offset = -1;          // -1: find the line by name
  std::string name;         // the line's name, when offset is -1
  bool active_low = false;  // asserted when the pin reads 0
  double debounce_s = 0.0;  // inputs: a change counts once it has held this long
};

inline constexpr std::size_t kMaxLimitLines = 8;

// A numbered program line: an output a program switches with M62..M65 P
// `number` (and M7/M8/user M-codes that name it), or an input M66 P `number`
// reads.
struct GpioProgramLine {
  int number = 0;  // 0..255
  GpioLineConfig line;
};

struct GpioConfig {
  std::string consumer = "kerf";  // the label the kernel shows for requested lines
  GpioLineConfig torch;           // output
  GpioLineConfig arc_ok;          // inputs from here on
  GpioLineConfig estop;
  std::vector<GpioLineConfig> limits;  // at most kMaxLimitLines
  GpioLineConfig hold;            // feed-hold button
  GpioLineConfig cycle_start;     // resume after a hold
  GpioLineConfig reset;           // unlatches the E-stop chain (its rising edge)
  GpioLineConfig watchdog;        // output: toggles every cycle while all is well
  GpioLineConfig thc_lock;        // output: torch-height control holds (board's thc_lock, torch on)
  std::vector<GpioProgramLine> outputs;  // program outputs (M62..M65 P)
  std::vector<GpioProgramLine> inputs;   // program inputs (M66 P)
};

struct GpioInputs {
  bool arc_ok = false;
  bool estop = false;
  bool hold = false;
  bool cycle_start = false;
  bool reset = false;
  std::uint8_t limit_count = 0;  // how many limit lines exist
  std::array<bool, kMaxLimitLines> limit{};
  bool any_limit() const {
    for (std::uint8_t i = 0; i < limit_count; ++i)
      if (limit[i]) return true;
    return false;
  }
};

class Gpio {
 public:
  virtual ~Gpio() = default;
  // Samples every input at `now_s` (a monotonic clock, seconds; the
  // debounce runs on it). False on an I/O error (last_error says which line).
  virtual bool read(double now_s, GpioInputs& in) = 0;
  // Drives the torch output. False on an I/O error.
  virtual bool set_torch(bool on) = 0;
  // Drives the watchdog output, when there is one (none: nothing to do). False on an I/O error.
  virtual bool set_watchdog(bool level) {
    (void)level;
    return true;
  }
  // Drives the thc_lock output (torch-height control holds), when there is
  // one (none: nothing to do). False on an I/O error.
  virtual bool set_thc_lock(bool on) {
    (void)on;
    return true;
  }
  // Drives program output `number` (M62..M65 P) when there is such a line
  // (none: nothing to do). False on an I/O error.
  virtual bool set_output(int number, bool on) {
    (void)number;
    (void)on;
    return true;
  }
  // Every program output off (a fault, an E-stop, the job's end). False on an I/O error.
  virtual bool outputs_off() { return true; }
  // Reads program input `number` (M66 P) at `now_s`, debounced; a missing
  // line reads false. False on an I/O error.
  virtual bool read_input(int number, double now_s, bool& value) {
    (void)number;
    (void)now_s;
    value = false;
    return true;
  }
  virtual const char* last_error() const = 0;
};

}  // namespace kerf::hal
