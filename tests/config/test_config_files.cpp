// The shipped example configs, the defaults, and the file-level errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "config/config.hpp"

namespace kerf::config {
namespace {

const std::string kExamples = KERF_EXAMPLES_DIR;

TEST(ConfigFiles, PlasmaTableExampleLoads) {
  Config c;
  std::string error;
  ASSERT_TRUE(load(kExamples + "/kerf.toml", c, error)) << error;
  EXPECT_EQ(c.file, kExamples + "/kerf.toml");
  ASSERT_EQ(c.machine.axes.size(), 2u);
  EXPECT_EQ(c.machine.axes[0].name, "x");
  EXPECT_EQ(c.machine.axes[1].name, "y");
  EXPECT_EQ(c.machine.axes[1].counts_per_mm, 200);
  // The soft limits: a real table sets them.
  EXPECT_TRUE(c.machine.axes[0].has_min && c.machine.axes[0].has_max);
  EXPECT_EQ(c.machine.axes[0].max, 3000);
  EXPECT_EQ(c.machine.axes[1].max, 1500);
  EXPECT_EQ(c.machine.axes[1].min, 0);
  EXPECT_EQ(c.machine.max_feed, 12000);
  EXPECT_EQ(c.machine.rapid_feed, 10000);
  EXPECT_EQ(c.machine.accel, 1500);  // written as an integer
  EXPECT_EQ(c.machine.servo_period, 0.001);
  EXPECT_EQ(c.machine.cycle, 0.002);

  EXPECT_EQ(c.link.kind, Link::Kind::modbus_tcp);
  EXPECT_STREQ(to_string(c.link.kind), "modbus-tcp");
  EXPECT_EQ(c.link.host, "192.168.10.20");
  EXPECT_EQ(c.link.port, 502);
  EXPECT_EQ(c.link.unit, 17);
  EXPECT_EQ(c.link.timeout, 1.0);

  EXPECT_EQ(c.gpio.consumer, "kerf");
  EXPECT_TRUE(c.gpio.torch.used);
  EXPECT_EQ(c.gpio.torch.chip, "gpiochip0");
  EXPECT_EQ(c.gpio.torch.offset, 17);
  EXPECT_FALSE(c.gpio.torch.active_low);
  EXPECT_TRUE(c.gpio.estop.used);
  EXPECT_EQ(c.gpio.estop.offset, 22);
  EXPECT_TRUE(c.gpio.estop.active_low);
  EXPECT_DOUBLE_EQ(c.gpio.estop.debounce_s, 0.005);
  EXPECT_EQ(c.gpio.arc_ok.offset, 27);
  EXPECT_EQ(c.gpio.hold.offset, 23);
  EXPECT_EQ(c.gpio.cycle_start.offset, 24);
  EXPECT_EQ(c.gpio.reset.offset, 25);
  EXPECT_EQ(c.gpio.watchdog.offset, 26);
  EXPECT_EQ(c.machine.ferror, 1.0);
  EXPECT_EQ(c.machine.min_ferror, 0.25);
  ASSERT_EQ(c.gpio.limits.size(), 2u);
  EXPECT_EQ(c.gpio.limits[0].offset, 5);
  EXPECT_EQ(c.gpio.limits[1].offset, 6);
  EXPECT_EQ(c.gpio.limits[1].chip, "gpiochip0");
  EXPECT_TRUE(c.gpio.limits[1].active_low);
  ASSERT_EQ(c.gpio.outputs.size(), 1u);
  EXPECT_EQ(c.gpio.outputs[0].number, 1);
  EXPECT_EQ(c.gpio.outputs[0].line.offset, 12);
  EXPECT_EQ(c.gpio.outputs[0].line.chip, "gpiochip0");
  ASSERT_EQ(c.gpio.inputs.size(), 1u);
  EXPECT_EQ(c.gpio.inputs[0].number, 0);
  EXPECT_TRUE(c.gpio.inputs[0].line.active_low);
  EXPECT_DOUBLE_EQ(c.gpio.inputs[0].line.debounce_s, 0.01);
  EXPECT_EQ(c.program.analog_ignore, std::vector<int>{0});

  EXPECT_STREQ(kerf::job::to_string(c.fit.criterion), "band");
  EXPECT_EQ(c.fit.tol, 0.025);
  EXPECT_STREQ(kerf::job::to_string(c.fit.numeric), "double");
  EXPECT_EQ(c.cut.feed, 3000);
  EXPECT_EQ(c.cut.pierce_delay, 0.5);
  EXPECT_EQ(c.cut.arc_ok_timeout, 3.0);
  EXPECT_EQ(c.rt.priority, 80);
  EXPECT_TRUE(c.rt.lock_memory);
}

TEST(ConfigFiles, SimulatorExampleLoadsWithoutGpioLines) {
  Config c;
  std::string error;
  ASSERT_TRUE(load(kExamples + "/sim.toml", c, error)) << error;
  EXPECT_EQ(c.link.kind, Link::Kind::modbus_tcp);
  EXPECT_EQ(c.link.host, "127.0.0.1");
  EXPECT_EQ(c.link.port, 1502);
  EXPECT_EQ(c.machine.axes.size(), 2u);
  EXPECT_EQ(c.machine.axes[0].counts_per_mm, 1000);
  EXPECT_FALSE(c.gpio.torch.used);
  EXPECT_FALSE(c.gpio.estop.used);
  EXPECT_TRUE(c.gpio.limits.empty());
  EXPECT_EQ(c.rt.priority, 0);
  EXPECT_FALSE(c.rt.lock_memory);
}

// The z-axis example: z's own feed and accel, and the interpreter told to run Z as moves.
TEST(ConfigFiles, ZAxisExampleGivesZLimits) {
  Config c;
  std::string error;
  ASSERT_TRUE(load(kExamples + "/sim_z.toml", c, error)) << error;
  ASSERT_EQ(c.machine.axes.size(), 3u);
  EXPECT_EQ(c.machine.axes[2].name, "z");
  const auto z = z_limits(c.machine);
  EXPECT_TRUE(z.configured());
  EXPECT_DOUBLE_EQ(z.feed, 3000.0 / 60.0);
  EXPECT_DOUBLE_EQ(z.accel, 500.0);
  EXPECT_DOUBLE_EQ(z.period, 0.001);
  EXPECT_TRUE(interp_settings(c, false).z_axis);
  // z homes up by default (a torch clears the sheet); x and y towards -.
  EXPECT_EQ(c.machine.axes[2].home_dir, 1);
  EXPECT_EQ(c.machine.axes[0].home_dir, -1);
  EXPECT_EQ(c.machine.axes[1].home_dir, -1);
  // Without z's own keys: the machine's rapid feed and accel; without z: none.
  c.machine.axes[2].feed = c.machine.axes[2].accel = 0;
  EXPECT_DOUBLE_EQ(z_limits(c.machine).feed, c.machine.rapid_feed / 60.0);
  EXPECT_DOUBLE_EQ(z_limits(c.machine).accel, c.machine.accel);
  c.machine.axes.pop_back();
  EXPECT_FALSE(z_limits(c.machine).configured());
  EXPECT_FALSE(interp_settings(c, false).z_axis);
}

TEST(ConfigFiles, Defaults) {
  const Config c = defaults();
  ASSERT_EQ(c.machine.axes.size(), 2u);
  EXPECT_EQ(c.machine.axes[0].name, "x");
  EXPECT_EQ(c.machine.axes[1].name, "y");
  EXPECT_EQ(c.machine.axes[0].counts_per_mm, 1000);
  EXPECT_EQ(c.machine.max_feed, 10000);
  EXPECT_EQ(c.machine.rapid_feed, 10000);
  EXPECT_EQ(c.machine.accel, 1000);
  EXPECT_EQ(c.machine.jerk, 0);
  EXPECT_EQ(c.machine.servo_period, 0.001);
  EXPECT_EQ(c.machine.cycle, 0.002);
  EXPECT_EQ(c.link.kind, Link::Kind::modbus_tcp);
  EXPECT_EQ(c.link.host, "127.0.0.1");
  EXPECT_EQ(c.link.port, 502);
  EXPECT_EQ(c.link.unit, 17);
  EXPECT_EQ(c.link.timeout, 1.0);
  EXPECT_EQ(c.gpio.consumer, "kerf");
  EXPECT_FALSE(c.gpio.torch.used);
  EXPECT_TRUE(c.gpio.limits.empty());
  EXPECT_STREQ(kerf::job::to_string(c.fit.criterion), "band");
  EXPECT_EQ(c.fit.tol, 0.025);
  EXPECT_STREQ(kerf::job::to_string(c.fit.numeric), "double");
  EXPECT_EQ(c.cut.feed, 3000);
  EXPECT_EQ(c.cut.pierce_delay, 0.5);
  EXPECT_EQ(c.cut.arc_ok_timeout, 3.0);
  EXPECT_EQ(c.rt.priority, 0);
  EXPECT_FALSE(c.rt.lock_memory);
}

TEST(ConfigFiles, SmallestFileKeepsTheDefaults) {
  Config c;
  std::string error;
  ASSERT_TRUE(parse("[link]\nkind = \"modbus-tcp\"\n", "min.toml", c, error)) << error;
  const Config d = defaults();
  EXPECT_EQ(c.file, "min.toml");
  EXPECT_EQ(c.machine.axes.size(), d.machine.axes.size());
  EXPECT_EQ(c.machine.accel, d.machine.accel);
  EXPECT_EQ(c.link.port, d.link.port);
  EXPECT_EQ(c.cut.feed, d.cut.feed);
}

TEST(ConfigFiles, FitNumericFixed) {
  Config c;
  std::string error;
  ASSERT_TRUE(parse("[link]\nkind = \"modbus-tcp\"\n[fit]\ncriterion = \"vertex\"\nnumeric = \"fixed\"\n",
                    "fixed.toml", c, error))
      << error;
  EXPECT_STREQ(kerf::job::to_string(c.fit.criterion), "vertex");
  EXPECT_STREQ(kerf::job::to_string(c.fit.numeric), "fixed");
}

// Every criterion runs in fixed point, the biarc fitter too.
TEST(ConfigFiles, FitNumericFixedBiarc) {
  Config c;
  std::string error;
  ASSERT_TRUE(parse("[link]\nkind = \"modbus-tcp\"\n[fit]\ncriterion = \"biarc\"\nnumeric = \"fixed\"\n",
                    "fixed.toml", c, error))
      << error;
  EXPECT_STREQ(kerf::job::to_string(c.fit.criterion), "biarc");
  EXPECT_STREQ(kerf::job::to_string(c.fit.numeric), "fixed");
}

TEST(ConfigFiles, OtherLinksAndLinesByName) {
  Config c;
  std::string error;
  const char* can =
      "[machine]\nmax_feed = 5000\n"
      "[[machine.axis]]\nname = \"x\"\ncounts_per_mm = 100\n"
      "[[machine.axis]]\nname = \"y\"\ncounts_per_mm = 100\n"
      "[[machine.axis]]\nname = \"z\"\ncounts_per_mm = 400.5\n"
      "[link]\nkind = \"can\"\niface = \"can1\"\nnode_ids = [3, 4, 5]\nsync_ms = 2\n"
      "[gpio]\n[gpio.estop]\nname = \"ESTOP\"\n[gpio.torch]\nchip = \"/dev/gpiochip1\"\noffset = 4\n"
      "[cut]\nfeed = 2000\n";
  ASSERT_TRUE(parse(can, "can.toml", c, error)) << error;
  EXPECT_EQ(c.link.kind, Link::Kind::can);
  EXPECT_EQ(c.link.iface, "can1");
  EXPECT_EQ(c.link.node_ids, (std::vector<int>{3, 4, 5}));
  EXPECT_EQ(c.link.sync_ms, 2);
  EXPECT_EQ(c.machine.axes[2].counts_per_mm, 400.5);
  EXPECT_EQ(c.machine.rapid_feed, 5000);  // defaults to max_feed
  EXPECT_EQ(c.gpio.estop.offset, -1);
  EXPECT_EQ(c.gpio.estop.name, "ESTOP");
  EXPECT_EQ(c.gpio.estop.chip, "");  // searched on every chip
  EXPECT_EQ(c.gpio.torch.chip, "/dev/gpiochip1");

  const char* rtu = "[link]\nkind = \"modbus-rtu\"\ndevice = \"/dev/ttyUSB0\"\nbaud = 38400\nunit = 2\n";
  ASSERT_TRUE(parse(rtu, "rtu.toml", c, error)) << error;
  EXPECT_EQ(c.link.kind, Link::Kind::modbus_rtu);
  EXPECT_EQ(c.link.device, "/dev/ttyUSB0");
  EXPECT_EQ(c.link.baud, 38400);
  EXPECT_EQ(c.link.unit, 2);
}

TEST(ConfigFiles, SafetyLinesAndFollowingError) {
  Config c;
  std::string error;
  const char* text =
      "[machine]\nferror = 2.0\nmin_ferror = 0.5\n"
      "[link]\nkind = \"modbus-tcp\"\n"
      "[gpio]\nchip = \"gpiochip0\"\n[gpio.reset]\noffset = 5\nactive_low = true\ndebounce_ms = 10\n"
      "[gpio.watchdog]\noffset = 6\n";
  ASSERT_TRUE(parse(text, "safety.toml", c, error)) << error;
  EXPECT_EQ(c.machine.ferror, 2.0);
  EXPECT_EQ(c.machine.min_ferror, 0.5);
  EXPECT_TRUE(c.gpio.reset.used);
  EXPECT_EQ(c.gpio.reset.offset, 5);
  EXPECT_TRUE(c.gpio.reset.active_low);
  EXPECT_EQ(c.gpio.reset.debounce_s, 0.01);
  EXPECT_TRUE(c.gpio.watchdog.used);
  EXPECT_EQ(c.gpio.watchdog.offset, 6);
  const Config d = defaults();
  EXPECT_EQ(d.machine.ferror, 1.0);
  EXPECT_EQ(d.machine.min_ferror, 0.25);
  EXPECT_FALSE(d.gpio.reset.used);
  EXPECT_FALSE(d.gpio.watchdog.used);
}

TEST(ConfigFiles, BadFileLeavesTheConfigUntouched) {
  Config c = defaults();
  c.cut.feed = 1234;
  std::string error;
  EXPECT_FALSE(parse("[link]\nkind = \"can\"\n[cut]\nfeed = 99\n", "bad.toml", c, error));
  EXPECT_EQ(c.cut.feed, 1234);
  EXPECT_EQ(c.link.kind, Link::Kind::modbus_tcp);
}

TEST(ConfigFiles, SyntaxErrorHasItsLine) {
  Config c;
  std::string error;
  EXPECT_FALSE(parse("[link]\nkind = \"modbus-tcp\"\n\n[cut]\nfeed = = 3\n", "syn.toml", c, error));
  EXPECT_EQ(error.rfind("syn.toml:5: syntax error: ", 0), 0u) << error;
  EXPECT_GT(error.size(), std::string("syn.toml:5: syntax error: ").size());
}

TEST(ConfigFiles, MissingFile) {
  Config c;
  std::string error;
  EXPECT_FALSE(load(kExamples + "/no-such.toml", c, error));
  EXPECT_EQ(error, kExamples + "/no-such.toml: cannot read: No such file or directory");
}

TEST(ConfigFiles, DirectoryIsNotAFile) {
  Config c;
  std::string error;
  EXPECT_FALSE(load(kExamples, c, error));
  EXPECT_EQ(error, kExamples + ": cannot read: Is a directory");
}

}  // namespace
}  // namespace kerf::config
