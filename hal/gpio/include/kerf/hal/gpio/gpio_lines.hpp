// The libgpiod backend's pure logic, shared by the v1 and v2 layers and
// testable without a kernel GPIO chip: which lines a GpioConfig asks for,
// how a chip is addressed, range and duplicate checks, and the error texts.
#pragma once

#include <string>
#include <vector>

#include "kerf/hal/gpio.hpp"

namespace kerf::hal::gpio_lines {

struct ChipInfo {
  std::string path;   // /dev/gpiochip0
  std::string name;   // gpiochip0 (the kernel's name)
  std::string label;  // pinctrl-bcm2835 (the driver's label)
  int num_lines = 0;
};

// One used line of the configuration, named as the errors name it.
struct LineRole {
  std::string role;  // "torch", "arc_ok", "estop", "limit 0", "hold", "cycle_start", "reset", "watchdog"
  const GpioLineConfig* cfg = nullptr;
  bool output = false;
  int limit_index = -1;  // limits only
  int number = -1;       // program outputs and inputs: the M62..M66 P number
};

// Where a line ended up.
struct LineAddress {
  std::string chip;  // chip name (gpiochip0)
  int offset = -1;
};

// The used lines of `cfg`, torch first, then the program outputs ("output
// N") and inputs ("input N"). False with `error` when the configuration
// itself is wrong (too many limits, neither offset nor name, negative or
// non-finite debounce, a program number out of 0..255 or given twice).
bool list_lines(const GpioConfig& cfg, std::vector<LineRole>& out, std::string& error);

// The device path a chip spec names: "gpiochip3" and "3" -> "/dev/gpiochip3",
// a path stays as is. Empty when the spec is a chip label, which is found by
// opening every chip and comparing labels.
std::string chip_path_for(const std::string& spec);

// The GPIO character devices under `dev_dir`, in chip-number order.
std::vector<std::string> list_chip_paths(const char* dev_dir = "/dev");

// Checks a configured offset against the chip's line count.
bool check_offset(const std::string& role, const ChipInfo& chip, int offset, std::string& error);

// No two roles may share a line: the second request would fail as busy
// against kerf itself, which is a confusing message for a config mistake.
bool check_distinct(const std::vector<LineRole>& roles, const std::vector<LineAddress>& where,
                    std::string& error);

// Error texts.
std::string no_such_chip(const std::string& role, const std::string& spec);
std::string not_a_chip(const std::string& role, const std::string& path);
std::string cannot_open(const std::string& role, const std::string& path, int err);
std::string busy(const std::string& role, const std::string& chip, int offset,
                 const std::string& consumer);
// `searched`: the chips looked at (one when the config names the chip).
std::string name_not_found(const std::string& role, const std::string& name,
                           const std::vector<ChipInfo>& searched, bool chip_given);
std::string name_ambiguous(const std::string& role, const std::string& name,
                           const std::string& chip_a, const std::string& chip_b);
std::string request_failed(const std::string& role, const std::string& chip, int offset, int err);

}  // namespace kerf::hal::gpio_lines
