// Random paths, feeds, limits, holds and overrides: the invariants hold in
// every run (on the path, never back, never past the end, the end reached
// exactly, acceleration and jerk within their limits, holds come to rest).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "motion_helpers.hpp"

namespace kerf::motion {
namespace {

using namespace test;

struct Scenario {
  std::vector<Seg> path;
  std::vector<double> feeds;
  MotionConfig<double> config;
};

Scenario random_scenario(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scenario sc;
  V at{100 * u(rng) - 50, 100 * u(rng) - 50};
  double heading = 2 * kPi * u(rng);
  const int n = 1 + static_cast<int>(12 * u(rng));
  for (int i = 0; i < n; ++i) {
    const double len = std::pow(10.0, 2 * u(rng) - 1.5);  // 0.03 .. 3 mm
    if (u(rng) < 0.5) {
      sc.path.push_back(line_from(at, heading, len));
    } else {
      const double r = std::pow(10.0, 2 * u(rng) - 0.5);
      const double turn = (u(rng) < 0.5 ? -1 : 1) * std::min(len / r, 1.5 * kPi);
      sc.path.push_back(arc_from(at, heading, r, turn));
      heading += turn;
    }
    at = sc.path.back().end;
    if (u(rng) < 0.3) heading += (u(rng) - 0.5) * kPi;  // a corner (or a small kink)
    sc.feeds.push_back(10 + 190 * u(rng));
  }
  const double jerk = u(rng) < 0.5 ? 0.0 : std::pow(10.0, 4 + 2 * u(rng));
  sc.config = config(u(rng) < 0.5 ? 1e-3 : 2.5e-4, 200 + 4800 * u(rng), 5 * u(rng), 1000, jerk);
  return sc;
}

TEST(MotionRandom, InvariantsHoldOnRandomPathsWithHoldsAndOverrides) {
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int run = 0; run < 120; ++run) {
    const Scenario sc = random_scenario(rng);
    const MotionConfig<double>& c = sc.config;
    std::vector<QueuedSegment<double>> slots(1 + static_cast<std::size_t>(5 * u(rng)));
    std::vector<double> window(Interpolator<double>::jerk_window_size(c));
    Interpolator<double> ip(Span<QueuedSegment<double>>(slots.data(), slots.size()),
                            Span<double>(window.data(), window.size()));
    ASSERT_EQ(ip.configure(c), Status::ok);
    const double total = path_length(sc.path);
    std::vector<double> s{0.0, 0.0, 0.0};
    std::size_t next = 0;
    Setpoint<double> p;
    bool holding = false;
    for (int k = 0;; ++k) {
      ASSERT_LT(k, 2000000) << "run " << run << " never finished";
      while (next < sc.path.size() && ip.free_slots() > 0) {
        ASSERT_EQ(ip.push({sc.path[next], sc.feeds[next], static_cast<std::uint32_t>(next)}),
                  Status::ok);
        ++next;
      }
      if (k % 97 == 13) {
        ASSERT_EQ(ip.set_override(10 + 190 * u(rng)), Status::ok);
      }
      if (!holding && u(rng) < 0.002) {
        ip.hold();
        holding = true;
      }
      if (holding && p.state == MotionState::held && u(rng) < 0.05) {
        ip.resume();
        holding = false;
      }
      p = ip.step();
      const V want = path_point(sc.path, p.s);
      ASSERT_LE(std::hypot(p.position.x - want.x, p.position.y - want.y), 1e-9)
          << "run " << run << " s " << p.s;
      ASSERT_GE(p.s, s.back()) << "run " << run;
      ASSERT_LE(p.s, total + 1e-9) << "run " << run;
      s.push_back(p.s);
      if (p.state == MotionState::done && next == sc.path.size()) break;
    }
    EXPECT_EQ(p.position, sc.path.back().end) << "run " << run;
    for (int i = 0; i < 3; ++i) s.push_back(s.back());
    const double t = c.period;
    const double slack = 1e-12 / (t * t);  // rounding of s, as an acceleration
    for (std::size_t k = 3; k < s.size(); ++k) {
      const double d2 = s[k] - 2 * s[k - 1] + s[k - 2];
      ASSERT_LE(std::fabs(d2) / (t * t), c.accel * (1 + 1e-9) + slack) << "run " << run;
      if (c.jerk > 0) {
        const double d3 = s[k] - 3 * s[k - 1] + 3 * s[k - 2] - s[k - 3];
        ASSERT_LE(std::fabs(d3) / (t * t * t), c.jerk * (1 + 1e-9) + slack / t) << "run " << run;
      }
    }
  }
}

}  // namespace
}  // namespace kerf::motion
