// The demo job (the ESGI report's parabola, band fit at the report's
// tolerance) as segments for a SegmentLink, and a pusher that keeps the
// link's queue full with credit, as the controller does.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "job/fit_job.hpp"
#include "kerf/geom/segment.hpp"
#include "kerf/hal/segment_link.hpp"

namespace kerf::test {

struct DemoJob {
  io::PointFile points;
  std::vector<Segment<double>> path;
  std::vector<hal::SegmentCommand> segments;
  double tol = 0.0183;
};

inline DemoJob demo_job(double feed) {
  DemoJob j;
  const std::string file = std::string(KERF_EXAMPLES_DIR) + "/parabola.txt";
  if (!job::read_job(file, job::Criterion::band, j.points)) throw std::runtime_error("cannot read " + file);
  std::vector<fit::Piece<double>> pieces;
  std::string err;
  Status st{};
  if (!job::fit_job(j.points.points, {}, j.tol, job::Criterion::band, pieces, err, st)) throw std::runtime_error(err);
  std::uint32_t seq = 0;
  for (const auto& p : pieces) {
    j.path.push_back(p.segment);
    hal::SegmentCommand c;
    c.seq = ++seq;
    c.kind = p.segment.kind;
    c.end = p.segment.end;
    c.centre = p.segment.centre;
    c.dir = p.segment.dir;
    c.feed = feed;
    j.segments.push_back(c);
  }
  return j;
}

// Pushes what the link has credit for, from `next` on; returns the next one.
inline std::size_t push_some(hal::SegmentLink& link, const std::vector<hal::SegmentCommand>& segs, std::size_t next) {
  hal::BoardStatus st;
  link.status(st);
  while (next < segs.size() && st.credit > 0) {
    if (link.push(segs[next], st) != hal::LinkError::none) {
      ADD_FAILURE() << link.last_error();
      return segs.size();
    }
    ++next;
  }
  return next;
}

inline double distance_to_path(const std::vector<Segment<double>>& path, Vec2<double> p) {
  double best = 1e300;
  for (const auto& s : path) best = std::min(best, distance_to_segment(s, p));
  return best;
}

inline double distance_to_polyline(const std::vector<Vec2<double>>& pts, Vec2<double> p) {
  double best = 1e300;
  for (std::size_t i = 1; i < pts.size(); ++i) best = std::min(best, distance_to_line_segment(pts[i - 1], pts[i], p));
  return best;
}

}  // namespace kerf::test
