// Shared by the motion tests: building paths, running the interpolator to the
// end, and an independent evaluator of "the point at path length s" written
// with <cmath>, separately from core's path_geometry.hpp.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "kerf/motion/interpolator.hpp"

namespace kerf::motion::test {

using Seg = Segment<double>;
using V = Vec2<double>;

inline constexpr double kPi = 3.14159265358979323846;

// An arc from `from`, leaving in direction `heading` (radians), turning by
// `turn` radians (> 0 left/CCW, < 0 right/CW) on radius r.
inline Seg arc_from(V from, double heading, double r, double turn) {
  const int e = turn > 0 ? 1 : -1;
  const V normal{-std::sin(heading) * e, std::cos(heading) * e};  // towards the centre
  const V c = from + normal * r;
  const double a0 = std::atan2(from.y - c.y, from.x - c.x);
  const V end = c + V{std::cos(a0 + turn), std::sin(a0 + turn)} * r;
  return Seg::arc(from, end, c, e);
}

inline Seg line_from(V from, double heading, double len) {
  return Seg::line(from, from + V{std::cos(heading), std::sin(heading)} * len);
}

// Length and the point at distance u, computed from scratch.
inline double seg_length(const Seg& s) {
  if (!s.is_arc()) return std::hypot(s.end.x - s.start.x, s.end.y - s.start.y);
  const double r = std::hypot(s.start.x - s.centre.x, s.start.y - s.centre.y);
  double a0 = std::atan2(s.start.y - s.centre.y, s.start.x - s.centre.x);
  double a1 = std::atan2(s.end.y - s.centre.y, s.end.x - s.centre.x);
  double sweep = s.dir > 0 ? a1 - a0 : a0 - a1;
  while (sweep <= 0) sweep += 2 * kPi;
  return r * sweep;
}

inline V seg_point(const Seg& s, double u) {
  const double len = seg_length(s);
  if (!s.is_arc()) return s.start + (s.end - s.start) * (u / len);
  const double r = std::hypot(s.start.x - s.centre.x, s.start.y - s.centre.y);
  const double a0 = std::atan2(s.start.y - s.centre.y, s.start.x - s.centre.x);
  const double a = a0 + (s.dir > 0 ? 1 : -1) * u / r;
  return {s.centre.x + r * std::cos(a), s.centre.y + r * std::sin(a)};
}

// The point of a whole path at path length s (clamped to its ends).
inline V path_point(const std::vector<Seg>& path, double s) {
  double base = 0;
  for (const Seg& g : path) {
    const double len = seg_length(g);
    if (s <= base + len) return seg_point(g, s - base);
    base += len;
  }
  return path.back().end;
}

inline double path_length(const std::vector<Seg>& path) {
  double sum = 0;
  for (const Seg& g : path) sum += seg_length(g);
  return sum;
}

inline MotionConfig<double> config(double period, double accel, double corner_deg = 1.0,
                                   double cpm = 1000.0, double jerk = 0.0) {
  MotionConfig<double> c;
  c.jerk = jerk;
  c.period = period;
  c.accel = accel;
  c.corner_angle = corner_deg * kPi / 180;
  c.counts_per_mm = {cpm, cpm};
  return c;
}

// Runs a whole path (pushing as room frees up) and returns every setpoint
// up to and including the first one in state done.
inline std::vector<Setpoint<double>> run_path(const std::vector<Seg>& path,
                                              const std::vector<double>& feeds,
                                              const MotionConfig<double>& c,
                                              std::size_t capacity = 64) {
  std::vector<QueuedSegment<double>> slots(capacity);
  std::vector<double> window(Interpolator<double>::jerk_window_size(c));
  Interpolator<double> ip(Span<QueuedSegment<double>>(slots.data(), slots.size()),
                          Span<double>(window.data(), window.size()));
  if (ip.configure(c) != Status::ok) return {};
  std::vector<Setpoint<double>> out;
  std::size_t next = 0;
  for (;;) {
    while (next < path.size() && ip.free_slots() > 0)
      if (ip.push({path[next], feeds[next], static_cast<std::uint32_t>(next)}) == Status::ok) ++next;
      else return {};
    out.push_back(ip.step());
    if (out.back().state == MotionState::done) return out;
  }
}

inline std::vector<Setpoint<double>> run_path(const std::vector<Seg>& path, double feed,
                                              const MotionConfig<double>& c,
                                              std::size_t capacity = 64) {
  return run_path(path, std::vector<double>(path.size(), feed), c, capacity);
}

// Speeds and accelerations along the path from the setpoints' s, with the
// head at rest before the first and after the last setpoint.
inline std::vector<double> step_lengths(const std::vector<Setpoint<double>>& sp) {
  std::vector<double> steps;
  double prev = 0;
  for (const auto& p : sp) {
    steps.push_back(p.s - prev);
    prev = p.s;
  }
  steps.push_back(0.0);
  return steps;
}

}  // namespace kerf::motion::test
