// The fixed-point biarc fit of the ESGI'104 parabola (tol 0.05), printed as
// raw Q31.32 values, against one expected text (fixed_biarc_parabola.expected).
// This file is built twice: into kerf_unit_tests (64-bit hosts use
// __int128 for products, quotients and roots) and into
// kerf_fixed_portable_tests (KERF_FIXED_PORTABLE: the 32-bit limbs that
// 32-bit targets and Cortex-M compile). Both must print the same text, so
// the biarc fitter's fixed-point result does not depend on the target.
#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "kerf/core/fixed.hpp"
#include "kerf/core/fixed_convert.hpp"
#include "kerf/fit/biarc.hpp"
#include "kerf/fit/biarc/tangent.hpp"

namespace {

using kerf::Fixed;
using kerf::Vec2;

std::string hex(Fixed v) {
  char b[24];
  std::snprintf(b, sizeof b, "%016" PRIx64, static_cast<std::uint64_t>(v.raw()));
  return b;
}

std::string hex(Vec2<Fixed> v) { return hex(v.x) + " " + hex(v.y); }

TEST(FixedBiarcParabola, SameTextWithAndWithoutInt128) {
  constexpr std::size_t n = 200;
  std::vector<Vec2<Fixed>> p(n), t(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = 500.0 - 500.0 * static_cast<double>(k) / (n - 1);
    const double u = 1.0 - x / 500.0;
    p[k] = {kerf::fixed_from_double(x), kerf::fixed_from_double(300.0 - 200.0 * u * u)};
  }
  kerf::fit::estimate_tangents<Fixed>({p.data(), n}, {t.data(), n});
  const Fixed tol = Fixed(0.05);
  const std::vector<kerf::fit::BandWidth<Fixed>> w(n, {tol, tol});
  std::vector<std::uint32_t> words(kerf::fit::biarc_workspace_words(n));
  std::vector<kerf::fit::BandVertex<Fixed>> vertices(n);
  std::vector<Vec2<Fixed>> scaled(n);
  std::vector<kerf::fit::BiarcPiece<Fixed>> out(n - 1);
  const auto r = kerf::fit::fit_biarc_min_count<Fixed>(
      {p.data(), n}, {t.data(), n}, {w.data(), n}, {},
      {{words.data(), words.size()}, {vertices.data(), n}, {scaled.data(), n}}, {out.data(), out.size()});
  ASSERT_TRUE(r.ok()) << kerf::to_string(r.status());
  // += throughout: armhf GCC 12 warns (-Wrestrict) on "literal" + std::string&&.
  std::string text = "fixed biarcs ";
  text += std::to_string(r.value().pieces);
  text += " max error ";
  text += hex(r.value().max_error);
  text += "\n";
  for (std::uint32_t k = 0; k < r.value().pieces; ++k) {
    const kerf::fit::BiarcPiece<Fixed>& b = out[k];
    text += std::to_string(b.first) + " -> " + std::to_string(b.last) + " joint " + hex(b.joint) + "\n";
    for (const kerf::Segment<Fixed>& s : b.arc) {
      if (!s.is_arc()) {
        text += "  line\n";
        continue;
      }
      text += "  arc centre ";
      text += hex(s.centre);
      text += s.dir > 0 ? " ccw\n" : " cw\n";
    }
  }
  std::ifstream in(KERF_FIXED_BIARC_EXPECTED);
  std::stringstream want;
  want << in.rdbuf();
  if (std::getenv("KERF_PRINT_FIXED_BIARC") != nullptr) std::printf("%s", text.c_str());
  ASSERT_FALSE(want.str().empty()) << KERF_FIXED_BIARC_EXPECTED;
  EXPECT_EQ(text, want.str());
  EXPECT_EQ(text.rfind("fixed biarcs 3 ", 0), 0u);  // as in double
}

}  // namespace
