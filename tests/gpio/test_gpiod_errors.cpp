// open_gpiod's error paths through the real libgpiod. This machine's kernel
// has no GPIO chip (no /dev/gpiochip*), and Debian's kernels carry neither
// gpio-mockup nor gpio-sim, so the paths that need a chip (offset range,
// busy line) are tested on gpio_lines directly (test_gpio_lines.cpp).
#include "kerf/hal/gpio/gpiod_gpio.hpp"

#include <gtest/gtest.h>

#include "kerf/hal/gpio/gpio_lines.hpp"

namespace kerf::hal {
namespace {

GpioLineConfig at(const char* chip, int offset) {
  GpioLineConfig l;
  l.used = true;
  l.chip = chip;
  l.offset = offset;
  return l;
}

GpioLineConfig named(const char* chip, const char* name) {
  GpioLineConfig l;
  l.used = true;
  l.chip = chip;
  l.name = name;
  return l;
}

std::string open_error(const GpioConfig& cfg) {
  std::string error;
  std::unique_ptr<Gpio> gpio = open_gpiod(cfg, error);
  EXPECT_EQ(gpio, nullptr);
  return error;
}

TEST(GpiodErrors, NoSuchChipByName) {
  GpioConfig cfg;
  cfg.torch = at("gpiochip99", 3);
  EXPECT_EQ(open_error(cfg), "gpio: torch: no such chip \"gpiochip99\"");
}

TEST(GpiodErrors, NoSuchChipByPathAndByNumber) {
  GpioConfig cfg;
  cfg.arc_ok = at("/dev/gpiochip99", 3);
  EXPECT_EQ(open_error(cfg), "gpio: arc_ok: no such chip \"/dev/gpiochip99\"");
  cfg.arc_ok = at("99", 3);
  EXPECT_EQ(open_error(cfg), "gpio: arc_ok: no such chip \"99\"");
}

TEST(GpiodErrors, NoSuchChipByLabel) {
  GpioConfig cfg;
  cfg.estop = at("kerf-no-such-label", 4);
  EXPECT_EQ(open_error(cfg), "gpio: estop: no such chip \"kerf-no-such-label\"");
}

TEST(GpiodErrors, NotAGpioChip) {
  GpioConfig cfg;
  cfg.hold = at("/dev/null", 0);
  EXPECT_EQ(open_error(cfg), "gpio: hold: /dev/null is not a GPIO chip");
}

TEST(GpiodErrors, LineNameSearchedOnEveryChip) {
  GpioConfig cfg;
  cfg.limits = {named("", "KERF_NO_SUCH_LINE")};
  const std::string error = open_error(cfg);
  if (gpio_lines::list_chip_paths().empty())  // as on this build machine
    EXPECT_EQ(error, "gpio: limit 0: no line named \"KERF_NO_SUCH_LINE\" (no GPIO chips found under /dev)");
  else
    EXPECT_EQ(error.rfind("gpio: limit 0: no line named \"KERF_NO_SUCH_LINE\" on any of ", 0), 0u) << error;
}

TEST(GpiodErrors, LineNameOnAMissingChip) {
  GpioConfig cfg;
  cfg.cycle_start = named("gpiochip98", "START");
  EXPECT_EQ(open_error(cfg), "gpio: cycle_start: no such chip \"gpiochip98\"");
}

TEST(GpiodErrors, ConfigErrorsComeBeforeAnyChipIsOpened) {
  GpioConfig cfg;
  cfg.torch = at("", 3);
  EXPECT_EQ(open_error(cfg), "gpio: torch: an offset needs a chip");
  cfg.torch.used = false;
  cfg.arc_ok.used = true;
  EXPECT_EQ(open_error(cfg), "gpio: arc_ok: neither an offset nor a line name is set");
}

TEST(Gpiod, NoLinesConfiguredOpensAndReadsNothing) {
  // A machine with no GPIO at all still gets a working (empty) Gpio.
  GpioConfig cfg;
  cfg.limits.resize(2);  // two limit slots, neither wired
  std::string error;
  std::unique_ptr<Gpio> gpio = open_gpiod(cfg, error);
  ASSERT_NE(gpio, nullptr) << error;
  GpioInputs in;
  in.estop = true;
  ASSERT_TRUE(gpio->read(0.0, in));
  EXPECT_FALSE(in.estop);
  EXPECT_EQ(in.limit_count, 2);
  EXPECT_TRUE(gpio->set_torch(true));  // no torch line: nothing to drive
}

TEST(Gpiod, ReportsItsApi) {
#ifdef KERF_GPIOD_V2
  EXPECT_STREQ(gpiod_api_name(), "libgpiod 2");
#else
  EXPECT_STREQ(gpiod_api_name(), "libgpiod 1.6");
#endif
}

}  // namespace
}  // namespace kerf::hal
