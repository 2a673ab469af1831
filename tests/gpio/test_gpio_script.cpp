// The GPIO script format: good scripts and each kind of bad line.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "kerf/sim/scripted_gpio.hpp"

namespace kerf::sim {
namespace {

using Kind = GpioEvent::Kind;

TEST(GpioScript, ParsesEveryEventWithCommentsAndBlankLines) {
  const char* text =
      "# a cut with faults\n"
      "0 no-arc\n"
      "\n"
      "0.8 arc-lost   # mid-cut\n"
      "1.25 estop on\n"
      "1.5\testop off\r\n"
      "2.0 limit 1 on\n"
      "3.0 hold\n"
      "3.5 hold 0.5\n"
      "4 cycle-start\n";
  std::vector<GpioEvent> ev;
  std::string error;
  ASSERT_TRUE(parse_gpio_script(text, "s.gpio", 2, ev, error)) << error;
  ASSERT_EQ(ev.size(), 8u);
  EXPECT_EQ(ev[0].kind, Kind::no_arc);
  EXPECT_EQ(ev[0].t_s, 0.0);
  EXPECT_EQ(ev[1].kind, Kind::arc_lost);
  EXPECT_EQ(ev[1].t_s, 0.8);
  EXPECT_EQ(ev[2].kind, Kind::estop);
  EXPECT_TRUE(ev[2].on);
  EXPECT_EQ(ev[2].t_s, 1.25);
  EXPECT_EQ(ev[3].kind, Kind::estop);
  EXPECT_FALSE(ev[3].on);
  EXPECT_EQ(ev[4].kind, Kind::limit);
  EXPECT_EQ(ev[4].limit, 1);
  EXPECT_TRUE(ev[4].on);
  EXPECT_EQ(ev[5].kind, Kind::hold);
  EXPECT_EQ(ev[5].duration_s, 0.0);  // the default press
  EXPECT_EQ(ev[6].duration_s, 0.5);
  EXPECT_EQ(ev[7].kind, Kind::cycle_start);
  EXPECT_EQ(ev[7].t_s, 4.0);
}

struct BadLine {
  const char* text;
  const char* error;
};

class GpioScriptBad : public ::testing::TestWithParam<BadLine> {};

TEST_P(GpioScriptBad, NamesFileLineAndReasonAndLeavesOutputAlone) {
  std::vector<GpioEvent> ev{GpioEvent{}};
  std::string error;
  EXPECT_FALSE(parse_gpio_script(GetParam().text, "job.gpio", 2, ev, error));
  EXPECT_EQ(error, GetParam().error);
  EXPECT_EQ(ev.size(), 1u);
}

INSTANTIATE_TEST_SUITE_P(
    Lines, GpioScriptBad,
    ::testing::Values(
        BadLine{"1 estop on\n2 explode\n", "job.gpio:2: unknown event \"explode\""},
        BadLine{"abc estop on\n", "job.gpio:1: bad time \"abc\" (seconds >= 0)"},
        BadLine{"1.5s estop on\n", "job.gpio:1: bad time \"1.5s\" (seconds >= 0)"},
        BadLine{"-1 estop on\n", "job.gpio:1: bad time \"-1\" (seconds >= 0)"},
        BadLine{"inf estop on\n", "job.gpio:1: bad time \"inf\" (seconds >= 0)"},
        BadLine{"# c\n2 estop on\n1 estop off\n",
                "job.gpio:3: time 1 goes backwards (the event before is at 2)"},
        BadLine{"1 limit 2 on\n", "job.gpio:1: limit 2 out of range (2 limit lines)"},
        BadLine{"1 limit x on\n", "job.gpio:1: limit needs an index and on or off (limit 0 on)"},
        BadLine{"1 limit 0\n", "job.gpio:1: limit needs an index and on or off (limit 0 on)"},
        BadLine{"1 estop maybe\n", "job.gpio:1: estop needs on or off"},
        BadLine{"1 estop\n", "job.gpio:1: estop needs on or off"},
        BadLine{"1 arc-lost now\n", "job.gpio:1: unexpected \"now\" after arc-lost"},
        BadLine{"1 estop on off\n", "job.gpio:1: unexpected \"off\" after estop"},
        BadLine{"1 hold 0\n", "job.gpio:1: bad press duration \"0\" (seconds > 0)"},
        BadLine{"1.0\n", "job.gpio:1: missing event after the time"}));

TEST(GpioScript, AppendsToEventsAlreadyThere) {
  std::vector<GpioEvent> ev;
  std::string error;
  ASSERT_TRUE(parse_gpio_fault("estop@5", 0, ev, error)) << error;
  ASSERT_TRUE(parse_gpio_script("1 hold\n", "s", 0, ev, error)) << error;
  ASSERT_EQ(ev.size(), 2u);
  EXPECT_EQ(ev[0].kind, Kind::estop);
  EXPECT_EQ(ev[1].kind, Kind::hold);
}

TEST(GpioScript, LoadsAFileAndNamesItInErrors) {
  const std::string path = ::testing::TempDir() + "kerf_gpio_script_test.gpio";
  {
    std::ofstream f(path);
    f << "0.5 estop on\n0.25 estop off\n";
  }
  std::vector<GpioEvent> ev;
  std::string error;
  EXPECT_FALSE(load_gpio_script(path, 0, ev, error));
  EXPECT_EQ(error, path + ":2: time 0.25 goes backwards (the event before is at 0.5)");
  {
    std::ofstream f(path);
    f << "0.5 estop on\n";
  }
  ASSERT_TRUE(load_gpio_script(path, 0, ev, error)) << error;
  ASSERT_EQ(ev.size(), 1u);  // the failed load above added nothing
  EXPECT_EQ(ev[0].t_s, 0.5);
  std::remove(path.c_str());
  EXPECT_FALSE(load_gpio_script(path, 0, ev, error));
  EXPECT_EQ(error, path + ": cannot open the GPIO script");
}

TEST(GpioFault, CommandLineSpecs) {
  std::vector<GpioEvent> ev;
  std::string error;
  ASSERT_TRUE(parse_gpio_fault("estop@1.25", 0, ev, error)) << error;
  ASSERT_EQ(ev.size(), 1u);
  EXPECT_EQ(ev[0].kind, Kind::estop);
  EXPECT_TRUE(ev[0].on);
  EXPECT_EQ(ev[0].t_s, 1.25);
  ev.clear();
  ASSERT_TRUE(parse_gpio_fault("limit-1@2:0.5", 2, ev, error)) << error;
  ASSERT_EQ(ev.size(), 2u);  // on at 2, off at 2.5
  EXPECT_EQ(ev[0].kind, Kind::limit);
  EXPECT_EQ(ev[0].limit, 1);
  EXPECT_TRUE(ev[0].on);
  EXPECT_EQ(ev[1].limit, 1);
  EXPECT_FALSE(ev[1].on);
  EXPECT_EQ(ev[1].t_s, 2.5);
  ev.clear();
  ASSERT_TRUE(parse_gpio_fault("hold@3:0.25", 0, ev, error)) << error;
  ASSERT_TRUE(parse_gpio_fault("arc-lost@0.8", 0, ev, error)) << error;
  ASSERT_EQ(ev.size(), 2u);
  EXPECT_EQ(ev[0].kind, Kind::hold);
  EXPECT_EQ(ev[0].duration_s, 0.25);
  EXPECT_EQ(ev[1].kind, Kind::arc_lost);
}

TEST(GpioFault, BadSpecsAppendNothing) {
  std::vector<GpioEvent> ev;
  std::string error;
  EXPECT_FALSE(parse_gpio_fault("estop", 0, ev, error));
  EXPECT_EQ(error, "--fault estop: expected KIND@SECONDS[:DURATION]");
  EXPECT_FALSE(parse_gpio_fault("melt@1", 0, ev, error));
  EXPECT_EQ(error, "--fault melt@1: unknown GPIO fault \"melt\"");
  EXPECT_FALSE(parse_gpio_fault("estop@soon", 0, ev, error));
  EXPECT_EQ(error, "--fault estop@soon: bad time \"soon\" (seconds >= 0)");
  EXPECT_FALSE(parse_gpio_fault("hold@1:0", 0, ev, error));
  EXPECT_EQ(error, "--fault hold@1:0: bad duration \"0\" (seconds > 0)");
  EXPECT_FALSE(parse_gpio_fault("limit-2@1", 2, ev, error));
  EXPECT_EQ(error, "--fault limit-2@1: no limit line 2 (2 limit lines)");
  EXPECT_FALSE(parse_gpio_fault("no-arc@1:2", 0, ev, error));
  EXPECT_EQ(error, "--fault no-arc@1:2: no-arc takes no duration");
  EXPECT_TRUE(ev.empty());
}

}  // namespace
}  // namespace kerf::sim
