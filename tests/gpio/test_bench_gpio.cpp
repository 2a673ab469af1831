// machine::BenchGpio, the lines of a bench without a torch: the inputs are the
// lines' (here scripted), the torch never reaches them, and arc-OK follows the
// commanded torch only when no arc-OK line is configured.
#include "machine/bench_gpio.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "kerf/sim/scripted_gpio.hpp"

namespace kerf::machine {
namespace {

hal::GpioInputs read_at(hal::Gpio& g, double t) {
  hal::GpioInputs in;
  EXPECT_TRUE(g.read(t, in)) << g.last_error();
  return in;
}

std::unique_ptr<sim::ScriptedGpio> lines_with_estop_at(double t) {
  auto lines = std::make_unique<sim::ScriptedGpio>();
  std::string error;
  sim::GpioEvent e;
  e.t_s = t;
  e.kind = sim::GpioEvent::Kind::estop;
  EXPECT_TRUE(lines->add(e, error)) << error;
  return lines;
}

TEST(BenchGpio, EstopComesFromTheLines) {
  BenchGpio g(lines_with_estop_at(2.0), false);
  EXPECT_FALSE(read_at(g, 1.0).estop);
  EXPECT_TRUE(read_at(g, 2.5).estop);
}

TEST(BenchGpio, WithoutAnArcOkLineTheArcFollowsTheCommandedTorch) {
  auto lines = lines_with_estop_at(100.0);
  sim::ScriptedGpio& raw = *lines;
  BenchGpio g(std::move(lines), false);
  EXPECT_FALSE(read_at(g, 0.0).arc_ok);
  ASSERT_TRUE(g.set_torch(true));
  EXPECT_TRUE(read_at(g, 0.001).arc_ok);
  EXPECT_FALSE(raw.torch());  // no torch output is ever driven
  ASSERT_TRUE(g.set_torch(false));
  EXPECT_FALSE(read_at(g, 0.002).arc_ok);
}

TEST(BenchGpio, AnArcOkLineIsReadAsConfigured) {
  BenchGpio g(lines_with_estop_at(100.0), true);
  ASSERT_TRUE(g.set_torch(true));
  // The scripted lines never saw the torch, so their arc-OK stays off.
  EXPECT_FALSE(read_at(g, 1.0).arc_ok);
}

}  // namespace
}  // namespace kerf::machine
