// The host half of the Cortex-M comparison: the fixed-point parabola fit
// prints exactly the text the emulated Cortex-M4 must print.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "../mcu/fixed_parabola.hpp"

namespace {

TEST(FixedParabola, HostPrintsTheTextTheMcuMustMatch) {
  static kerf::mcu::FixedParabola st;
  char text[2048];
  kerf::mcu::fit_fixed_parabola(st, text, sizeof text);
  std::ifstream in(KERF_MCU_EXPECTED);
  std::stringstream want;
  want << in.rdbuf();
  ASSERT_FALSE(want.str().empty()) << KERF_MCU_EXPECTED;
  EXPECT_EQ(std::string(text), want.str());
  EXPECT_EQ(std::string(text).rfind("fixed pieces 5 ", 0), 0u);
  EXPECT_NE(std::string(text).find("\nfixed band pieces 5 "), std::string::npos);
}

}  // namespace
