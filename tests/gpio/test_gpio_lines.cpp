// The libgpiod backend's pure logic: the lines a config asks for, chip
// addressing, the range check against a chip's line count, duplicates, and
// the error texts. No kernel chip is needed (this machine has none).
#include "kerf/hal/gpio/gpio_lines.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <fstream>
#include <sys/stat.h>

namespace kerf::hal::gpio_lines {
namespace {

GpioLineConfig at(const char* chip, int offset) {
  GpioLineConfig l;
  l.used = true;
  l.chip = chip;
  l.offset = offset;
  return l;
}

TEST(GpioLines, ListsUsedLinesTorchFirstWithRoleNames) {
  GpioConfig cfg;
  cfg.torch = at("gpiochip0", 17);
  cfg.estop = at("gpiochip0", 4);
  cfg.limits = {at("gpiochip0", 5), GpioLineConfig{}, at("gpiochip0", 6)};
  cfg.cycle_start = at("gpiochip0", 7);
  std::vector<LineRole> roles;
  std::string error;
  ASSERT_TRUE(list_lines(cfg, roles, error)) << error;
  std::vector<std::string> names;
  for (const LineRole& r : roles) names.push_back(r.role);
  EXPECT_EQ(names, (std::vector<std::string>{"torch", "estop", "limit 0", "limit 2", "cycle_start"}));
  EXPECT_TRUE(roles[0].output);
  EXPECT_FALSE(roles[1].output);
  EXPECT_EQ(roles[3].limit_index, 2);
  EXPECT_EQ(roles[3].cfg, &cfg.limits[2]);
}

TEST(GpioLines, RejectsBadLineConfigs) {
  std::vector<LineRole> roles;
  std::string error;
  GpioConfig cfg;
  cfg.arc_ok.used = true;  // neither offset nor name
  EXPECT_FALSE(list_lines(cfg, roles, error));
  EXPECT_EQ(error, "gpio: arc_ok: neither an offset nor a line name is set");

  cfg = GpioConfig{};
  cfg.hold = at("gpiochip0", 3);
  cfg.hold.debounce_s = -0.01;
  EXPECT_FALSE(list_lines(cfg, roles, error));
  EXPECT_EQ(error, "gpio: hold: debounce must be a time >= 0 s");
  cfg.hold.debounce_s = std::nan("");
  EXPECT_FALSE(list_lines(cfg, roles, error));

  cfg = GpioConfig{};
  cfg.limits.resize(kMaxLimitLines + 1);
  EXPECT_FALSE(list_lines(cfg, roles, error));
  EXPECT_EQ(error, "gpio: 9 limit lines, at most 8");
}

TEST(GpioLines, ChipSpecsToPaths) {
  EXPECT_EQ(chip_path_for("gpiochip3"), "/dev/gpiochip3");
  EXPECT_EQ(chip_path_for("3"), "/dev/gpiochip3");
  EXPECT_EQ(chip_path_for("/dev/gpiochip0"), "/dev/gpiochip0");
  EXPECT_EQ(chip_path_for("pinctrl-bcm2835"), "");  // a label: searched
  EXPECT_EQ(chip_path_for("gpiochipX"), "");
  EXPECT_EQ(chip_path_for(""), "");
}

TEST(GpioLines, OffsetOutOfRange) {
  const ChipInfo chip{"/dev/gpiochip0", "gpiochip0", "pinctrl-bcm2835", 54};
  std::string error;
  EXPECT_TRUE(check_offset("arc_ok", chip, 0, error));
  EXPECT_TRUE(check_offset("arc_ok", chip, 53, error));
  EXPECT_FALSE(check_offset("arc_ok", chip, 54, error));
  EXPECT_FALSE(check_offset("arc_ok", chip, 99, error));
  EXPECT_EQ(error, "gpio: arc_ok: chip gpiochip0 has 54 lines, offset 99 is out of range");
  EXPECT_FALSE(check_offset("torch", chip, -2, error));
}

TEST(GpioLines, TwoRolesOnOneLineAreRefused) {
  GpioConfig cfg;
  cfg.estop = at("gpiochip0", 5);
  cfg.hold = at("/dev/gpiochip0", 5);
  std::vector<LineRole> roles;
  std::string error;
  ASSERT_TRUE(list_lines(cfg, roles, error));
  EXPECT_TRUE(check_distinct(roles, {{"gpiochip0", 5}, {"gpiochip1", 5}}, error));
  EXPECT_FALSE(check_distinct(roles, {{"gpiochip0", 5}, {"gpiochip0", 5}}, error));
  EXPECT_EQ(error, "gpio: hold: line 5 on gpiochip0 is already estop's");
}

TEST(GpioLines, ErrorTexts) {
  EXPECT_EQ(no_such_chip("torch", "gpiochip7"), "gpio: torch: no such chip \"gpiochip7\"");
  EXPECT_EQ(busy("torch", "gpiochip0", 17, "linuxcnc"),
            "gpio: torch: line 17 on gpiochip0 is busy (used by \"linuxcnc\")");
  EXPECT_EQ(busy("torch", "gpiochip0", 17, ""), "gpio: torch: line 17 on gpiochip0 is busy");
  const ChipInfo a{"/dev/gpiochip0", "gpiochip0", "x", 54};
  const ChipInfo b{"/dev/gpiochip1", "gpiochip1", "y", 8};
  EXPECT_EQ(name_not_found("estop", "ESTOP", {a}, true),
            "gpio: estop: no line named \"ESTOP\" on gpiochip0");
  EXPECT_EQ(name_not_found("estop", "ESTOP", {a, b}, false),
            "gpio: estop: no line named \"ESTOP\" on any of 2 chips (gpiochip0, gpiochip1)");
  EXPECT_EQ(name_not_found("estop", "ESTOP", {}, false),
            "gpio: estop: no line named \"ESTOP\" (no GPIO chips found under /dev)");
  EXPECT_EQ(name_ambiguous("estop", "ESTOP", "gpiochip0", "gpiochip1"),
            "gpio: estop: line name \"ESTOP\" is on both gpiochip0 and gpiochip1: set the chip");
  EXPECT_EQ(request_failed("hold", "gpiochip0", 3, EPERM),
            "gpio: hold: cannot request line 3 on gpiochip0: Operation not permitted");
}

TEST(GpioLines, ListsOnlyCharacterDevicesInChipOrder) {
  const std::string dir = ::testing::TempDir() + "kerf_gpio_dev";
  ::mkdir(dir.c_str(), 0700);
  std::ofstream(dir + "/gpiochip0") << "not a device";
  EXPECT_TRUE(list_chip_paths(dir.c_str()).empty());
  EXPECT_TRUE(list_chip_paths("/nonexistent-kerf-dir").empty());
  std::remove((dir + "/gpiochip0").c_str());
  ::rmdir(dir.c_str());
}

}  // namespace
}  // namespace kerf::hal::gpio_lines
