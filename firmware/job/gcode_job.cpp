// A G-code file as a job's cut paths (job/gcode_reader.hpp: read_gcode_job):
// the moves with the torch on, arcs sampled into points.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "job/gcode_reader.hpp"

namespace kerf::job {

namespace {

// An arc whose end lies on its circle: the end's distance from the centre is
// the start's within 0.01 mm (CAM rounding) plus 1e-4 of the radius.
// Otherwise (I or J is wrong) a cut would spiral or jump, so a job refuses
// it; `kerf weld` passes arcs through as written and does not ask.
bool arc_closes(const GBlock& b, std::string& reason) {
  const double* end = b.end_pos;
  const bool inches = b.inches;
  const double r0 = std::hypot(b.start[0] - b.centre[0], b.start[1] - b.centre[1]);
  const double r1 = std::hypot(end[0] - b.centre[0], end[1] - b.centre[1]);
  if (!(r0 > 0)) return reason = "an arc with its centre on its start point", false;
  const double slack = (inches ? 0.01 / kMmPerInch : 0.01) + 1e-4 * r0;
  if (std::fabs(r1 - r0) <= slack) return true;
  char buf[160];
  std::snprintf(buf, sizeof buf, "the arc's end is off its circle: radius %.6g at the start, %.6g at the end",
                r0, r1);
  reason = buf;
  return false;
}

// Points along an arc from `from` (exclusive) to `to` (inclusive), chord error
// below `chord`.
void sample_arc(Vec2<double> from, Vec2<double> to, Vec2<double> c, bool ccw, double chord,
                std::vector<Vec2<double>>& out) {
  const double r = (from - c).norm();
  const double a0 = std::atan2(from.y - c.y, from.x - c.x);
  const double a1 = std::atan2(to.y - c.y, to.x - c.x);
  const double two_pi = 2 * 3.14159265358979323846;
  double sweep = ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 1e-12) sweep += two_pi;  // equal ends: a full circle
  const double step = r > chord ? 2 * std::acos(1 - chord / r) : sweep;
  // At most 100000 points; a radius past ~1e13 chords makes the step 0
  // (1 - chord / r rounds to 1), and the quotient inf.
  constexpr double kMostPoints = 100000;
  const double parts = step > 0 ? std::ceil(sweep / step) : kMostPoints;
  const std::size_t n = static_cast<std::size_t>(std::clamp(parts, 1.0, kMostPoints));
  for (std::size_t k = 1; k < n; ++k) {
    const double a = a0 + (ccw ? 1 : -1) * sweep * static_cast<double>(k) / static_cast<double>(n);
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  out.push_back(to);
}

}  // namespace

bool gcode_job_from(const GcodeFile& g, io::PointFile& out, std::string& error) {
  out = io::PointFile{};
  out.file = g.file;
  auto refuse = [&](std::size_t line, const std::string& why) {
    out.ok = false;
    out.line = line;
    out.reason = why;
    error = g.file + ":" + std::to_string(line) + ": " + why;
    return false;
  };
  if (!g.ok) return refuse(g.line, g.reason);
  bool uses_torch = false;
  for (const GBlock& b : g.blocks)
    for (const GWord& w : b.words)
      if (w.letter == 'M' && (code10(w.value) == 30 || code10(w.value) == 40)) uses_torch = true;
  bool open = false;
  bool torch = false;
  std::size_t path_start = 0;
  auto close = [&] {
    if (open && out.points.size() - path_start < 2) {  // a lone point (a plunge): no path
      out.points.resize(path_start);
      out.point_lines.resize(path_start);
    } else if (open) {
      out.path_begin.push_back(path_start);
    }
    open = false;
  };
  auto add = [&](Vec2<double> p, std::size_t line, double scale) {
    p = {p.x * scale, p.y * scale};
    if (out.points.size() > path_start && out.points.back() == p) {
      ++out.duplicates_dropped;
      return;
    }
    out.points.push_back(p);
    out.point_lines.push_back(line);
  };
  std::vector<Vec2<double>> arc;
  for (const GBlock& b : g.blocks) {
    if (!b.unknown.empty()) return refuse(b.line, "unsupported word \"" + std::string(b.unknown.front()) + "\"");
    if (b.torch != torch) close();
    torch = b.torch;
    if (!b.moves) continue;
    const bool feed = b.motion != Motion::rapid;
    const bool cutting = feed && (!uses_torch || b.torch);
    if (!cutting) {
      close();
      continue;
    }
    if (!b.xy_plane && (b.motion == Motion::cw || b.motion == Motion::ccw))
      return refuse(b.line, "an arc outside the XY plane (G18/G19) cannot be cut");
    std::string why;
    if ((b.motion == Motion::cw || b.motion == Motion::ccw) && b.known_start && !arc_closes(b, why))
      return refuse(b.line, why);
    if (!b.known_start) {
      const bool xy_still = b.motion == Motion::linear && b.start[0] == b.end_pos[0] && b.start[1] == b.end_pos[1];
      if (xy_still) continue;  // a Z move before any X Y: no point of a path
      return refuse(b.line, "a cut from an unknown position (no absolute X and Y yet)");
    }
    const double scale = b.inches ? kMmPerInch : 1.0;
    const Vec2<double> from{b.start[0], b.start[1]};
    const Vec2<double> to{b.end_pos[0], b.end_pos[1]};
    if (!open) {
      open = true;
      path_start = out.points.size();
      add(from, b.line, scale);
    }
    if (b.motion == Motion::linear) {
      add(to, b.line, scale);
    } else {
      arc.clear();
      sample_arc(from, to, {b.centre[0], b.centre[1]}, b.motion == Motion::ccw, 0.001 / scale, arc);
      for (const Vec2<double>& p : arc) add(p, b.line, scale);
    }
  }
  close();
  if (out.path_begin.empty()) {
    refuse(0, "no cut moves (G1/G2/G3 with the torch on)");
    error = g.file + ": " + out.reason;
    return false;
  }
  out.ok = true;
  return true;
}

bool read_gcode_job(const std::string& path, io::PointFile& out, std::string& error) {
  const GcodeFile g = read_gcode(path);
  if (!g.ok) {
    out = io::PointFile{};
    out.file = g.file;
    out.line = g.line;
    out.reason = g.reason;
    error = describe_error(g);
    return false;
  }
  return gcode_job_from(g, out, error);
}

bool is_gcode_path(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return false;
  std::string ext;
  for (char c : path.substr(dot + 1)) ext += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* e : {"nc", "ngc", "gcode", "gco", "gc", "tap", "cnc"})
    if (ext == e) return true;
  return false;
}

}  // namespace kerf::job
