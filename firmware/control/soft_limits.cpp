#include "control/soft_limits.hpp"

#include <algorithm>
#include <cstdio>

namespace kerf::control {

namespace {

// "X 1.000 mm past max 1200.000", for the first side of `e` outside `l`; empty when inside.
std::string breach(const motion::SoftLimits<double>& l, const motion::Extent<double>& e) {
  const double lo[2] = {e.lo.x, e.lo.y}, hi[2] = {e.hi.x, e.hi.y};
  char text[120];
  for (int a = 0; a < 2; ++a) {
    if (!l.on[a]) continue;
    const char* name = a == 0 ? "X" : "Y";
    if (hi[a] > l.max[a]) {
      std::snprintf(text, sizeof text, "%s %.3f mm past max %.3f", name, hi[a] - l.max[a], l.max[a]);
      return text;
    }
    if (lo[a] < l.min[a]) {
      std::snprintf(text, sizeof text, "%s %.3f mm past min %.3f", name, l.min[a] - lo[a], l.min[a]);
      return text;
    }
  }
  return {};
}

std::size_t line_at(const io::PointFile& source, std::size_t point) {
  return point < source.point_lines.size() ? source.point_lines[point] : 0;
}

void take(motion::Extent<double>& box, const motion::Extent<double>& e) {
  box.lo = {std::min(box.lo.x, e.lo.x), std::min(box.lo.y, e.lo.y)};
  box.hi = {std::max(box.hi.x, e.hi.x), std::max(box.hi.y, e.hi.y)};
}

}  // namespace

motion::SoftLimits<double> soft_limits_of(const config::Machine& m) {
  motion::SoftLimits<double> l;
  for (std::size_t a = 0; a < 2 && a < m.axes.size(); ++a) {
    const config::Axis& axis = m.axes[a];
    l.on[a] = axis.has_min || axis.has_max;
    l.min[a] = axis.has_min ? axis.min : -1e300;
    l.max[a] = axis.has_max ? axis.max : 1e300;
  }
  return l;
}

bool fully_limited(const config::Machine& m) {
  return m.axes.size() >= 2 && m.axes[0].has_min && m.axes[0].has_max && m.axes[1].has_min && m.axes[1].has_max;
}

motion::Extent<double> job_extent(const FittedJob& fitted, const Vec2<double>* start) {
  const Vec2<double> first = start ? *start : fitted.job.paths.front().start;
  motion::Extent<double> box{first, first};
  for (const CutPath& p : fitted.job.paths) {
    Vec2<double> from = p.start;
    take(box, {from, from});
    for (const std::vector<hal::SegmentCommand>* list : {&p.before, &p.after})
      for (const hal::SegmentCommand& c : *list)
        if (!c.z_move) take(box, {c.end, c.end});
    for (const hal::SegmentCommand& s : p.segments) {
      take(box, motion::segment_extent(from, s));
      from = s.end;
    }
  }
  return box;
}

bool check_soft_limits(const FittedJob& fitted, const io::PointFile& source, const motion::SoftLimits<double>& limits,
                       const Vec2<double>* start, std::string& error, std::size_t first_path) {
  if (start && !limits.contains(*start)) {
    error = source.file + ": the machine starts outside the soft limits, at (" + std::to_string(start->x) + ", " +
            std::to_string(start->y) + "): " + breach(limits, {*start, *start});
    return false;
  }
  std::size_t piece = 0;
  for (std::size_t p = 0; p < fitted.job.paths.size(); ++p) {
    const CutPath& path = fitted.job.paths[p];
    const std::size_t base = p < fitted.path_point.size() ? fitted.path_point[p] : 0;
    std::string why = breach(limits, {path.start, path.start});
    for (const std::vector<hal::SegmentCommand>* list : {&path.before, &path.after})
      for (const hal::SegmentCommand& c : *list)  // a z axis's XY rapids: straight lines between these points
        if (why.empty() && !c.z_move) why = breach(limits, {c.end, c.end});
    if (!why.empty()) {  // the travel to the pierce point (a straight line between points checked)
      error = source.file + ":" + std::to_string(line_at(source, base)) + ": outside the soft limits: " + why +
              " (travel to or from path " +
              std::to_string(first_path + p + 1) + ")";
      return false;
    }
    Vec2<double> from = path.start;
    for (std::size_t k = 0; k < path.segments.size(); ++k, ++piece) {
      const hal::SegmentCommand& s = path.segments[k];
      why = breach(limits, motion::segment_extent(from, s));
      from = s.end;
      if (why.empty()) continue;
      // The line of the first source point outside, or of the piece's end
      // (the fit's bulge between points that are all inside).
      std::size_t line = 0;
      if (piece < fitted.pieces.size()) {
        const fit::Piece<double>& pc = fitted.pieces[piece];
        line = line_at(source, base + pc.last);
        for (std::size_t i = base + pc.first; i <= base + pc.last && i < source.points.size(); ++i)
          if (!limits.contains(source.points[i])) {
            line = line_at(source, i);
            break;
          }
      }
      error = source.file + ":" + std::to_string(line) + ": outside the soft limits: " + why + " (path " + std::to_string(first_path + p + 1) +
              ", segment " + std::to_string(k + 1) + ")";
      return false;
    }
  }
  return true;
}

}  // namespace kerf::control
