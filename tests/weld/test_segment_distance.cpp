// weld's distance from many samples to one segment
// (firmware/weld/segment_distance.hpp): core's distance_to_line_segment, bit for bit.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "kerf/geom/segment.hpp"
#include "weld/segment_distance.hpp"

namespace {

using kerf::weld::detail::SegmentDistance;
using P = kerf::Vec2<double>;

// Random segments at several scales (and a point segment), each measured from
// points around it: beside it, before its start, past its end, on its line
// and on its ends. Each distance is core's, bit for bit: write_piece's
// deviation then stays what the polyline scan (core's distance) would give.
TEST(SegmentDistance, SameBitsAsDistanceToLineSegment) {
  std::mt19937_64 rng(25);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int compared = 0;
  for (int s = 0; s < 2000; ++s) {
    const double scale = s % 3 == 0 ? 1e-3 : s % 3 == 1 ? 1.0 : 300.0;
    const P off{400 * unit(rng), 400 * unit(rng)};
    const P a = off + P{scale * unit(rng), scale * unit(rng)};
    const P b = s % 50 == 0 ? a : off + P{scale * unit(rng), scale * unit(rng)};
    const SegmentDistance to(a, b);
    std::vector<P> ps = {a, b, a + (b - a) * 0.5, a + (b - a) * -0.25, a + (b - a) * 1.25};
    for (int k = 0; k < 20; ++k)
      ps.push_back(a + (b - a) * (1.5 * unit(rng) + 0.5) + P{scale * unit(rng), scale * unit(rng)});
    for (const P& p : ps) {
      ASSERT_EQ(to(p), kerf::distance_to_line_segment(a, b, p)) << s;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 2000 * 25);
}

}  // namespace
