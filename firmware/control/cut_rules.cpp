#include "control/cut_rules.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kerf::control {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Angle swept from a to b around c in direction dir, in (0, 2 pi].
double sweep(Vec2<double> a, Vec2<double> b, Vec2<double> c, int dir) {
  const Vec2<double> u = a - c, v = b - c;
  double s = std::atan2(u.cross(v), u.dot(v)) * (dir > 0 ? 1 : -1);
  if (!(s > 0)) s += 2 * kPi;
  return s;
}

double seg_length(Vec2<double> from, const hal::SegmentCommand& s) {
  if (s.kind != SegmentKind::arc) return (s.end - from).norm();
  return (from - s.centre).norm() * sweep(from, s.end, s.centre, s.dir);
}

// The first `len` mm of segment s (from `from`), as a segment.
hal::SegmentCommand head_of(Vec2<double> from, const hal::SegmentCommand& s, double len) {
  hal::SegmentCommand h = s;
  if (s.kind != SegmentKind::arc) {
    h.end = from + (s.end - from) * (len / (s.end - from).norm());
    return h;
  }
  const Vec2<double> u = from - s.centre;
  const double r = u.norm();
  const double phi = std::atan2(u.y, u.x) + (s.dir > 0 ? 1 : -1) * len / r;
  h.end = s.centre + Vec2<double>{std::cos(phi), std::sin(phi)} * r;
  return h;
}

}  // namespace

bool is_closed(const CutPath& path) {
  if (path.segments.empty()) return false;
  const Vec2<double> gap = path.segments.back().end - path.start;
  return gap.norm() <= 1e-6 * (1 + std::max(std::fabs(path.start.x), std::fabs(path.start.y)));
}

double path_size(const CutPath& path) {
  Vec2<double> lo = path.start, hi = path.start;
  const auto take = [&](Vec2<double> p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  };
  Vec2<double> from = path.start;
  for (const hal::SegmentCommand& s : path.segments) {
    if (s.kind == SegmentKind::arc) {  // the bulges: the axis points the arc passes
      const Vec2<double> u = from - s.centre;
      const double r = u.norm(), a0 = std::atan2(u.y, u.x), sw = sweep(from, s.end, s.centre, s.dir);
      for (int q = 0; q < 4; ++q) {
        const double axis = q * kPi / 2;
        double d = (s.dir > 0 ? axis - a0 : a0 - axis);
        d = std::fmod(std::fmod(d, 2 * kPi) + 2 * kPi, 2 * kPi);
        if (d <= sw) take(s.centre + Vec2<double>{std::cos(axis), std::sin(axis)} * r);
      }
    }
    take(s.end);
    from = s.end;
  }
  return std::max(hi.x - lo.x, hi.y - lo.y);
}

std::vector<CutRuleNote> apply_cut_rules(FittedJob& fitted, const config::CutRules& rules) {
  std::vector<CutRuleNote> notes;
  std::vector<fit::Piece<double>> pieces;
  std::vector<std::size_t> piece_path;
  std::size_t next_piece = 0;
  for (std::size_t p = 0; p < fitted.job.paths.size(); ++p) {
    CutPath& path = fitted.job.paths[p];
    const std::size_t n = path.segments.size();
    for (std::size_t k = 0; k < n && next_piece < fitted.pieces.size(); ++k) {
      pieces.push_back(fitted.pieces[next_piece++]);
      piece_path.push_back(p);
    }
    const double size = path_size(path);
    const bool hole = is_closed(path) && size < rules.hole_diameter;
    if (hole) {
      for (hal::SegmentCommand& s : path.segments) s.feed *= rules.hole_feed / 100;
      notes.push_back({p, "hole", 0, size, rules.hole_feed});
    } else if (rules.arc_radius > 0) {
      Vec2<double> from = path.start;
      for (std::size_t k = 0; k < n; ++k) {
        hal::SegmentCommand& s = path.segments[k];
        const double r = (from - s.centre).norm();
        if (s.kind == SegmentKind::arc && r < rules.arc_radius) {
          s.feed *= rules.arc_feed / 100;
          notes.push_back({p, "arc", k, r, rules.arc_feed});
        }
        from = s.end;
      }
    }
    if (hole && rules.overcut > 0) {  // the path again from its start, for `overcut` mm
      double left = rules.overcut;
      Vec2<double> from = path.start;
      const std::size_t first_piece = pieces.size() - n;  // the path's own pieces: their source points
      for (std::size_t k = 0; k < n && left > 0; ++k) {
        const hal::SegmentCommand s = path.segments[k];
        const double len = seg_length(from, s);
        const hal::SegmentCommand piece = len <= left ? s : head_of(from, s, left);
        path.segments.push_back(piece);
        fit::Piece<double> fp = pieces[first_piece + k];
        fp.segment = piece.kind == SegmentKind::arc
                         ? Segment<double>::arc(from, piece.end, piece.centre, piece.dir)
                         : Segment<double>::line(from, piece.end);
        pieces.push_back(fp);
        piece_path.push_back(p);
        left -= std::min(len, left);
        from = s.end;
      }
      notes.push_back({p, "overcut", n, rules.overcut - left, rules.hole_feed});
    }
  }
  fitted.pieces = std::move(pieces);
  fitted.piece_path = std::move(piece_path);
  return notes;
}

std::string describe(const CutRuleNote& n, const config::CutRules& rules) {
  char line[160];
  if (n.rule == "hole")
    std::snprintf(line, sizeof line, "path %zu: hole %.6g mm < %.6g mm: %.6g %% feed", n.path + 1, n.value,
                  rules.hole_diameter, n.feed_percent);
  else if (n.rule == "arc")
    std::snprintf(line, sizeof line, "path %zu: segment %zu: arc r %.6g mm < %.6g mm: %.6g %% feed", n.path + 1,
                  n.segment + 1, n.value, rules.arc_radius, n.feed_percent);
  else
    std::snprintf(line, sizeof line, "path %zu: overcut %.6g mm past the start (segments from %zu), torch off at its end",
                  n.path + 1, n.value, n.segment + 1);
  return line;
}

void say_cut_rules(const std::string& file, const std::vector<CutRuleNote>& notes,
                   const config::CutRules& rules) {
  for (const CutRuleNote& n : notes) std::fprintf(stderr, "kerf: %s: %s\n", file.c_str(), describe(n, rules).c_str());
}

}  // namespace kerf::control
