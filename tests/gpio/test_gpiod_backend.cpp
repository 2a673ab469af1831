// The libgpiod backend's logic above the version seam, against fake chips
// (fake_gpiod.cpp): torch safety, active-low, debounce, line lookup, busy
// lines, I/O errors, and that every error path closes what it opened.
#include <gtest/gtest.h>

#include "fake_gpiod.hpp"
#include "kerf/hal/gpio/gpiod_gpio.hpp"

namespace kerf::hal {
namespace {

using fake_gpiod::world;

GpioLineConfig at(const char* chip, int offset, bool active_low = false, double debounce_s = 0) {
  GpioLineConfig l;
  l.used = true;
  l.chip = chip;
  l.offset = offset;
  l.active_low = active_low;
  l.debounce_s = debounce_s;
  return l;
}

GpioLineConfig named(const char* chip, const char* name) {
  GpioLineConfig l;
  l.used = true;
  l.chip = chip;
  l.name = name;
  return l;
}

class GpiodBackend : public ::testing::Test {
 protected:
  void SetUp() override {
    world() = fake_gpiod::World{};
    fake_gpiod::FakeChip c0{"gpiochip0", "pinctrl-bcm2835", std::vector<fake_gpiod::FakeLine>(54)};
    c0.lines[17].name = "TORCH";
    c0.lines[4].name = "ESTOP";
    fake_gpiod::FakeChip c1{"gpiochip1", "mcp23017", std::vector<fake_gpiod::FakeLine>(16)};
    c1.lines[2].name = "ARC_OK";
    world().chips["/dev/gpiochip0"] = c0;
    world().chips["/dev/gpiochip1"] = c1;
  }
  // Nothing stays open or requested once the backend is gone or failed.
  void TearDown() override {
    EXPECT_EQ(world().open_chips, 0);
    EXPECT_EQ(world().requested_lines, 0);
  }
  fake_gpiod::FakeLine& line(const char* path, int offset) {
    return world().chips.at(path).lines.at(static_cast<std::size_t>(offset));
  }
};

TEST_F(GpiodBackend, TorchStartsOffAndEndsOffActiveHigh) {
  GpioConfig cfg;
  cfg.torch = at("gpiochip0", 17);
  std::string error;
  {
    auto gpio = open_gpiod(cfg, error);
    ASSERT_NE(gpio, nullptr) << error;
    ASSERT_EQ(world().writes.size(), 1u);
    EXPECT_TRUE(world().writes[0].initial);
    EXPECT_FALSE(world().writes[0].high);
    EXPECT_EQ(line("/dev/gpiochip0", 17).consumer, "kerf");
    ASSERT_TRUE(gpio->set_torch(true));
    EXPECT_TRUE(line("/dev/gpiochip0", 17).level);
  }
  // The destructor drove it off before releasing.
  EXPECT_FALSE(world().writes.back().high);
  EXPECT_FALSE(line("/dev/gpiochip0", 17).level);
}

TEST_F(GpiodBackend, TorchActiveLowStartsAndEndsHigh) {
  GpioConfig cfg;
  cfg.torch = at("gpiochip0", 17, /*active_low=*/true);
  std::string error;
  {
    auto gpio = open_gpiod(cfg, error);
    ASSERT_NE(gpio, nullptr) << error;
    EXPECT_TRUE(world().writes.at(0).initial);
    EXPECT_TRUE(world().writes.at(0).high);  // logical off
    ASSERT_TRUE(gpio->set_torch(true));
    EXPECT_FALSE(line("/dev/gpiochip0", 17).level);
  }
  EXPECT_TRUE(line("/dev/gpiochip0", 17).level);
}

TEST_F(GpiodBackend, InputsAreActiveLowAndDebounced) {
  GpioConfig cfg;
  cfg.estop = at("gpiochip0", 4, /*active_low=*/true);
  cfg.arc_ok = named("", "ARC_OK");  // searched on every chip
  cfg.limits = {at("gpiochip1", 5, false, 0.25), GpioLineConfig{}};
  std::string error;
  auto gpio = open_gpiod(cfg, error);
  ASSERT_NE(gpio, nullptr) << error;
  line("/dev/gpiochip0", 4).level = true;  // E-stop chain closed: not asserted
  line("/dev/gpiochip1", 2).level = true;
  GpioInputs in;
  ASSERT_TRUE(gpio->read(1.0, in));
  EXPECT_FALSE(in.estop);
  EXPECT_TRUE(in.arc_ok);
  EXPECT_EQ(in.limit_count, 2);
  EXPECT_FALSE(in.any_limit());
  line("/dev/gpiochip0", 4).level = false;
  line("/dev/gpiochip1", 5).level = true;
  ASSERT_TRUE(gpio->read(1.125, in));
  EXPECT_TRUE(in.estop);      // no debounce on E-stop
  EXPECT_FALSE(in.limit[0]);  // limit 0 has been high for 0 s of its 0.25
  ASSERT_TRUE(gpio->read(1.375, in));
  EXPECT_TRUE(in.limit[0]);
  EXPECT_FALSE(in.limit[1]);
}

// gpio.thc_lock: its own output line, apart from the torch and the watchdog.
TEST_F(GpiodBackend, ThcLockOutputBesideTheTorch) {
  GpioConfig cfg;
  cfg.torch = at("gpiochip0", 17);
  cfg.thc_lock = at("gpiochip0", 20);
  std::string error;
  {
    auto gpio = open_gpiod(cfg, error);
    ASSERT_NE(gpio, nullptr) << error;
    EXPECT_FALSE(line("/dev/gpiochip0", 20).level);
    ASSERT_TRUE(gpio->set_thc_lock(true));
    EXPECT_TRUE(line("/dev/gpiochip0", 20).level);
    EXPECT_FALSE(line("/dev/gpiochip0", 17).level) << "thc_lock moved the torch";
    ASSERT_TRUE(gpio->set_thc_lock(false));
    EXPECT_FALSE(line("/dev/gpiochip0", 20).level);
    line("/dev/gpiochip0", 20).fail_io = true;
    EXPECT_FALSE(gpio->set_thc_lock(true));
    EXPECT_EQ(std::string(gpio->last_error()).rfind("gpio: thc_lock: ", 0), 0u) << gpio->last_error();
  }
}

TEST_F(GpiodBackend, ResetInputAndWatchdogOutputBesideTheOthers) {
  GpioConfig cfg;
  cfg.torch = at("gpiochip0", 17);
  cfg.watchdog = at("gpiochip0", 18, /*active_low=*/true);
  cfg.reset = at("gpiochip0", 19, /*active_low=*/true);
  cfg.limits = {at("gpiochip1", 5)};
  std::string error;
  {
    auto gpio = open_gpiod(cfg, error);
    ASSERT_NE(gpio, nullptr) << error;
    EXPECT_TRUE(line("/dev/gpiochip0", 18).level);  // active-low watchdog starts logically low
    ASSERT_TRUE(gpio->set_watchdog(true));
    EXPECT_FALSE(line("/dev/gpiochip0", 18).level);
    EXPECT_FALSE(line("/dev/gpiochip0", 17).level) << "the watchdog moved the torch";
    ASSERT_TRUE(gpio->set_watchdog(false));
    EXPECT_TRUE(line("/dev/gpiochip0", 18).level);
    line("/dev/gpiochip0", 19).level = false;  // reset pressed (active low)
    line("/dev/gpiochip1", 5).level = true;
    GpioInputs in;
    ASSERT_TRUE(gpio->read(1.0, in));
    EXPECT_TRUE(in.reset);
    EXPECT_TRUE(in.limit[0]);
    line("/dev/gpiochip0", 19).level = true;
    line("/dev/gpiochip1", 5).level = false;
    ASSERT_TRUE(gpio->read(1.1, in));
    EXPECT_FALSE(in.reset);
    EXPECT_FALSE(in.limit[0]);
    line("/dev/gpiochip0", 18).fail_io = true;
    EXPECT_FALSE(gpio->set_watchdog(true));
    EXPECT_EQ(std::string(gpio->last_error()).rfind("gpio: watchdog: ", 0), 0u) << gpio->last_error();
  }
}

TEST_F(GpiodBackend, LinesByNameAndChipLabel) {
  GpioConfig cfg;
  cfg.torch = named("pinctrl-bcm2835", "TORCH");
  cfg.estop = named("gpiochip0", "ESTOP");
  cfg.hold = at("mcp23017", 9);
  std::string error;
  auto gpio = open_gpiod(cfg, error);
  ASSERT_NE(gpio, nullptr) << error;
  EXPECT_EQ(line("/dev/gpiochip0", 17).consumer, "kerf");
  EXPECT_EQ(line("/dev/gpiochip0", 4).consumer, "kerf");
  EXPECT_EQ(line("/dev/gpiochip1", 9).consumer, "kerf");
}

TEST_F(GpiodBackend, OffsetOutOfRangeThroughOpen) {
  GpioConfig cfg;
  cfg.arc_ok = at("gpiochip0", 99);
  std::string error;
  EXPECT_EQ(open_gpiod(cfg, error), nullptr);
  EXPECT_EQ(error, "gpio: arc_ok: chip gpiochip0 has 54 lines, offset 99 is out of range");
}

TEST_F(GpiodBackend, BusyLineNamesItsConsumerAndReleasesTheOthers) {
  line("/dev/gpiochip1", 7).consumer = "linuxcnc";
  GpioConfig cfg;
  cfg.torch = at("gpiochip0", 17, /*active_low=*/true);  // requested first...
  cfg.estop = at("gpiochip0", 4);
  cfg.cycle_start = at("gpiochip1", 7);  // ...this one, last, is busy
  std::string error;
  EXPECT_EQ(open_gpiod(cfg, error), nullptr);
  EXPECT_EQ(error, "gpio: cycle_start: line 7 on gpiochip1 is busy (used by \"linuxcnc\")");
  EXPECT_EQ(line("/dev/gpiochip0", 4).consumer, "");
  EXPECT_EQ(line("/dev/gpiochip0", 17).consumer, "");
  EXPECT_TRUE(line("/dev/gpiochip0", 17).level);  // left logically off (active-low)
  EXPECT_EQ(world().chips.at("/dev/gpiochip1").lines[7].consumer, "linuxcnc");
}

TEST_F(GpiodBackend, NameErrors) {
  GpioConfig cfg;
  cfg.hold = named("gpiochip1", "HOLD");
  std::string error;
  EXPECT_EQ(open_gpiod(cfg, error), nullptr);
  EXPECT_EQ(error, "gpio: hold: no line named \"HOLD\" on gpiochip1");
  cfg.hold = named("gpiochip1", "ARC_OK");
  cfg.arc_ok = named("gpiochip1", "ARC_OK");
  EXPECT_EQ(open_gpiod(cfg, error), nullptr);
  EXPECT_EQ(error, "gpio: hold: line 2 on gpiochip1 is already arc_ok's");
  world().chips["/dev/gpiochip1"].lines[3].name = "ESTOP";
  cfg = GpioConfig{};
  cfg.estop = named("", "ESTOP");
  EXPECT_EQ(open_gpiod(cfg, error), nullptr);
  EXPECT_EQ(error, "gpio: estop: line name \"ESTOP\" is on both gpiochip0 and gpiochip1: set the chip");
  cfg.estop = named("", "E_STOP");
  EXPECT_EQ(open_gpiod(cfg, error), nullptr);
  EXPECT_EQ(error, "gpio: estop: no line named \"E_STOP\" on any of 2 chips (gpiochip0, gpiochip1)");
  cfg.estop = named("gpiochip0", "ESTOP");  // the chip is given: not ambiguous
  auto gpio = open_gpiod(cfg, error);
  EXPECT_NE(gpio, nullptr) << error;
}

TEST_F(GpiodBackend, IoErrorsAreReportedNotThrown) {
  GpioConfig cfg;
  cfg.torch = at("gpiochip0", 17);
  cfg.estop = at("gpiochip0", 4);
  std::string error;
  auto gpio = open_gpiod(cfg, error);
  ASSERT_NE(gpio, nullptr) << error;
  line("/dev/gpiochip0", 4).fail_io = true;
  GpioInputs in;
  EXPECT_FALSE(gpio->read(0.0, in));
  EXPECT_STREQ(gpio->last_error(),
               "gpio: estop: reading line 4 on gpiochip0 failed: Input/output error");
  line("/dev/gpiochip0", 17).fail_io = true;
  EXPECT_FALSE(gpio->set_torch(true));
  EXPECT_STREQ(gpio->last_error(),
               "gpio: torch: setting line 17 on gpiochip0 failed: Input/output error");
  line("/dev/gpiochip0", 17).fail_io = false;  // so the destructor can turn it off
}

// [[gpio.output]] / [[gpio.input]]: numbered program lines beside the torch.
TEST_F(GpiodBackend, ProgramOutputsToggleAndEndOffAndInputsAreDebounced) {
  GpioConfig cfg;
  cfg.torch = at("gpiochip0", 17);
  cfg.outputs = {{3, at("gpiochip0", 20)}, {4, at("gpiochip1", 5, /*active_low=*/true)}};
  cfg.inputs = {{1, at("gpiochip0", 21, /*active_low=*/true, /*debounce_s=*/0.01)}};
  std::string error;
  {
    auto gpio = open_gpiod(cfg, error);
    ASSERT_NE(gpio, nullptr) << error;
    // Requested logically off: active-low 4 starts high.
    EXPECT_FALSE(line("/dev/gpiochip0", 20).level);
    EXPECT_TRUE(line("/dev/gpiochip1", 5).level);
    EXPECT_EQ(line("/dev/gpiochip1", 5).consumer, "kerf");
    ASSERT_TRUE(gpio->set_output(3, true));
    ASSERT_TRUE(gpio->set_output(4, true));
    EXPECT_TRUE(line("/dev/gpiochip0", 20).level);
    EXPECT_FALSE(line("/dev/gpiochip1", 5).level);
    EXPECT_FALSE(line("/dev/gpiochip0", 17).level);  // the torch is not touched
    ASSERT_TRUE(gpio->outputs_off());
    EXPECT_FALSE(line("/dev/gpiochip0", 20).level);
    EXPECT_TRUE(line("/dev/gpiochip1", 5).level);
    ASSERT_TRUE(gpio->set_output(3, true));

    EXPECT_FALSE(gpio->set_output(9, true));
    EXPECT_STREQ(gpio->last_error(), "gpio: output 9: no such line ([[gpio.output]] number = 9)");
    bool v = true;
    line("/dev/gpiochip0", 21).level = true;  // released (active-low)
    ASSERT_TRUE(gpio->read_input(1, 0.0, v));
    EXPECT_FALSE(v);
    line("/dev/gpiochip0", 21).level = false;  // asserted
    ASSERT_TRUE(gpio->read_input(1, 0.005, v));
    EXPECT_FALSE(v);  // not yet held for 10 ms
    ASSERT_TRUE(gpio->read_input(1, 0.02, v));
    EXPECT_TRUE(v);
    EXPECT_FALSE(gpio->read_input(2, 0.025, v));
    EXPECT_STREQ(gpio->last_error(), "gpio: input 2: no such line ([[gpio.input]] number = 2)");
    line("/dev/gpiochip0", 21).fail_io = true;
    EXPECT_FALSE(gpio->read_input(1, 0.03, v));
    EXPECT_NE(std::string(gpio->last_error()).find("gpio: input 1: reading line 21 on gpiochip0 failed"),
              std::string::npos)
        << gpio->last_error();
  }
  // The destructor drove every program output off before releasing it.
  EXPECT_FALSE(line("/dev/gpiochip0", 20).level);
  EXPECT_TRUE(line("/dev/gpiochip1", 5).level);
}

TEST_F(GpiodBackend, ProgramLineErrors) {
  GpioConfig cfg;
  cfg.outputs = {{3, at("gpiochip0", 20)}, {3, at("gpiochip0", 21)}};
  std::string error;
  EXPECT_EQ(open_gpiod(cfg, error), nullptr);
  EXPECT_EQ(error, "gpio: output 3: configured twice");
  cfg.outputs = {{3, at("gpiochip0", 20)}};
  cfg.inputs = {{0, at("gpiochip0", 20)}};
  EXPECT_EQ(open_gpiod(cfg, error), nullptr);
  EXPECT_EQ(error, "gpio: input 0: line 20 on gpiochip0 is already output 3's");
  cfg.inputs = {{256, at("gpiochip0", 21)}};
  EXPECT_EQ(open_gpiod(cfg, error), nullptr);
  EXPECT_EQ(error, "gpio: input 256: the number must be 0..255");
  line("/dev/gpiochip0", 20).fail_io = true;
  cfg.inputs.clear();
  auto gpio = open_gpiod(cfg, error);
  ASSERT_NE(gpio, nullptr) << error;
  EXPECT_FALSE(gpio->set_output(3, true));
  EXPECT_NE(std::string(gpio->last_error()).find("gpio: output 3: setting line 20 on gpiochip0 failed"),
            std::string::npos)
      << gpio->last_error();
  EXPECT_FALSE(gpio->outputs_off());
}

}  // namespace
}  // namespace kerf::hal
