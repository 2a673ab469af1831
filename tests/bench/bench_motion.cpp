// Throughput of the constant-feed interpolator (setpoints per second, double)
// on: tangent-continuous arcs, lines, pieces much shorter than one period's
// travel (several joints per step), small circles (speed capped by v^2 / r),
// and 1 mm lines with small kinks run at 200 mm/s and 500 mm/s^2, whose
// braking distance (40 mm) makes the look-ahead span about 40 segments every
// period. The queue holds 64 segments and is refilled as they complete, as a
// motion board would. Prints, for each path, setpoints/s, the ratio to the
// 10 M/s target, and the time per segment run (push, look-ahead, stepping
// through it): the look-ahead's cost per segment. It asserts nothing about
// speed (machines are noisy).
//
// usage: kerf_bench_motion [--setpoints N]   (default 2e7 per path)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "kerf/motion/interpolator.hpp"

namespace {

using namespace kerf;
using namespace kerf::motion;

constexpr double kTarget = 10e6;  // setpoints/s: a 1 kHz loop then uses < 0.1 % of a core

enum class Shape { arcs, lines, short_pieces, small_circles, kinked };

// Segment k of an endless path of the given shape.
class PathSource {
 public:
  explicit PathSource(Shape shape) : shape_(shape) {}
  Segment<double> next() {
    const Vec2<double> a = at_;
    Segment<double> s;
    if (shape_ == Shape::arcs) {  // S-bends: 60 degrees on r = 50, alternating side
      const double r = 50, turn = M_PI / 3;
      const int e = (k_ % 2 == 0) ? 1 : -1;
      const Vec2<double> normal{-std::sin(heading_) * e, std::cos(heading_) * e};
      const Vec2<double> c = a + normal * r;
      const double a0 = std::atan2(a.y - c.y, a.x - c.x) + e * turn;
      at_ = c + Vec2<double>{std::cos(a0), std::sin(a0)} * r;
      heading_ += e * turn;
      s = Segment<double>::arc(a, at_, c, e);
    } else if (shape_ == Shape::small_circles) {  // one circle of r = 2, in halves
      const Vec2<double> c = a + Vec2<double>{k_ % 2 == 0 ? 2.0 : -2.0, 0};
      at_ = c + (c - a);
      s = Segment<double>::arc(a, at_, c, 1);
    } else if (shape_ == Shape::kinked) {  // 1 mm lines turning 0.5 degrees, left then right
      heading_ += (k_ / 8 % 2 == 0 ? 1 : -1) * M_PI / 360;
      at_ = a + Vec2<double>{std::cos(heading_), std::sin(heading_)};
      s = Segment<double>::line(a, at_);
    } else {
      const double len = shape_ == Shape::lines ? 20.0 : 0.01;
      at_ = a + Vec2<double>{0.6, 0.8} * len;
      s = Segment<double>::line(a, at_);
    }
    ++k_;
    return s;
  }

 private:
  Shape shape_;
  Vec2<double> at_{};
  double heading_ = 0;
  std::uint64_t k_ = 0;
};

struct Figures {
  double per_second = 0;
  double ns_per_segment = 0;
  std::int64_t checksum = 0;  // keeps the optimiser from dropping the work
};

Figures run(Shape shape, double jerk, std::uint64_t setpoints) {
  const bool kinked = shape == Shape::kinked;
  MotionConfig<double> c;
  c.jerk = jerk;
  c.period = 1e-3;
  c.accel = kinked ? 500 : 2000;
  c.corner_angle = M_PI / 180;
  c.counts_per_mm = {1000, 1000};
  std::vector<QueuedSegment<double>> slots(64);
  std::vector<double> window(Interpolator<double>::jerk_window_size(c));
  Interpolator<double> ip(Span<QueuedSegment<double>>(slots.data(), slots.size()),
                          Span<double>(window.data(), window.size()));
  if (ip.configure(c) != Status::ok) std::abort();
  PathSource src(shape);
  std::uint32_t seq = 0;
  Figures f;
  const auto t0 = std::chrono::steady_clock::now();
  for (std::uint64_t k = 0; k < setpoints; ++k) {
    while (ip.free_slots() > 0)
      if (ip.push({src.next(), kinked ? 200.0 : 100.0, seq++}) != Status::ok) std::abort();
    const Setpoint<double> p = ip.step();
    f.checksum += p.counts.x ^ p.counts.y;
  }
  const auto t1 = std::chrono::steady_clock::now();
  const double secs = std::chrono::duration<double>(t1 - t0).count();
  f.per_second = static_cast<double>(setpoints) / secs;
  const std::uint64_t segments = ip.completed_count();
  f.ns_per_segment = segments > 0 ? secs * 1e9 / static_cast<double>(segments) : 0;
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t n = 20000000;
  for (int i = 1; i + 1 < argc; i += 2)
    if (std::strcmp(argv[i], "--setpoints") == 0) n = std::strtoull(argv[i + 1], nullptr, 10);
  std::printf("constant-feed interpolator, double, 100 mm/s, 1 ms period, queue of 64\n");
  std::printf("%-40s %14s %10s %12s\n", "path", "setpoints/s", "x target", "ns/segment");
  const struct {
    Shape shape;
    double jerk;
    const char* name;
  } paths[] = {{Shape::arcs, 0, "arcs (r 50, 60 deg S-bends)"},
               {Shape::lines, 0, "collinear lines of 20 mm"},
               {Shape::short_pieces, 0, "lines of 0.01 mm (10 per step)"},
               {Shape::arcs, 1e5, "arcs, S-curve (jerk 1e5: 40 periods)"},
               {Shape::small_circles, 0, "half circles of r 2"},
               {Shape::kinked, 0, "1 mm lines, 0.5 deg kinks, 200 mm/s"}};
  for (const auto& p : paths) {
    const Figures f = run(p.shape, p.jerk, n);
    std::printf("%-40s %14.3e %10.2f %12.1f   (checksum %lld)\n", p.name, f.per_second,
                f.per_second / kTarget, f.ns_per_segment, static_cast<long long>(f.checksum));
  }
  return 0;
}
