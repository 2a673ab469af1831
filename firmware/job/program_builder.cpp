#include "job/program_builder.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace kerf::job {

namespace {


// Points along an arc from `from` (exclusive) to `to` (inclusive), chord
// error below `chord` (mm), at most 100000 of them.
void sample_arc(Vec2<double> from, Vec2<double> to, Vec2<double> c, bool ccw, double chord,
                std::vector<Vec2<double>>& out) {
  const double r = (from - c).norm();
  const double a0 = std::atan2(from.y - c.y, from.x - c.x);
  const double a1 = std::atan2(to.y - c.y, to.x - c.x);
  const double two_pi = 2 * 3.14159265358979323846;
  double sweep = ccw ? a1 - a0 : a0 - a1;
  while (sweep <= 1e-12) sweep += two_pi;  // equal ends: a full circle
  const double step = r > chord ? 2 * std::acos(1 - chord / r) : sweep;
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

ProgramBuilder::ProgramBuilder(bool z_axis, bool dry_run, const double start[2], GcodeProgram& out)
    : out_(out), pos_{start[0], start[1]}, z_axis_(z_axis), dry_run_(dry_run) {
  out_.final_z = 0;
}

void ProgramBuilder::close() {
  io::PointFile& p = out_.points;
  if (open_ && p.points.size() - path_start_ < 2) {  // a lone point: no path
    p.points.resize(path_start_);
    p.point_lines.resize(path_start_);
    out_.point_feed.resize(path_start_);
    pending_.insert(pending_.begin(), cur_.before.begin(), cur_.before.end());  // they lead on
  } else if (open_) {
    p.path_begin.push_back(path_start_);
    out_.paths.push_back(cur_);
    after_path_ = true;
  }
  open_ = false;
}

// z axis: the moves between paths (gcode_program.hpp).
void ProgramBuilder::push_xy(Vec2<double> to, std::size_t line) {
  if (to == pos_) return;
  pending_.push_back({false, to, z_, 0, line});
}

void ProgramBuilder::push_z(double z, double feed_mm_min, std::size_t line) {
  pending_.push_back({true, pos_, z, feed_mm_min, line});
  ++out_.z_moves;
}

void ProgramBuilder::add(Vec2<double> q, std::size_t line, double feed) {
  io::PointFile& p = out_.points;
  if (p.points.size() > path_start_ && p.points.back() == q) {
    ++p.duplicates_dropped;
    return;
  }
  p.points.push_back(q);
  p.point_lines.push_back(line);
  out_.point_feed.push_back(feed);
}

void ProgramBuilder::action(const Canon& c) {
  close();
  // The moves since the last path, before its first action, run right after it.
  if (after_path_ && !out_.paths.empty()) {
    std::vector<ProgramMove>& after = out_.paths.back().after;
    after.insert(after.end(), pending_.begin(), pending_.end());
    pending_.clear();
  }
  after_path_ = false;
  ProgramAction a;
  a.kind = c.kind;
  a.before_path = taken_ + out_.paths.size();
  a.line = c.line;
  a.index = c.index;
  a.mode = c.mode;
  a.value = c.value;
  a.sync = c.sync;
  a.at = pos_;
  out_.actions.push_back(a);
}

void ProgramBuilder::step(const Canon& c) {
  switch (c.kind) {
    case CanonKind::torch:
      if ((c.index == 1) != torch_) close();
      torch_ = c.index == 1;
      return;
    case CanonKind::tolerance: tol_ = c.value; return;
    case CanonKind::feed_percent: percent_ = c.value; return;  // applies to the moves after it
    case CanonKind::tool:
      if (c.value >= 0) pierce_ = c.value;  // the material's pierce delay
      action(c);
      return;
    case CanonKind::dwell:
    case CanonKind::pause:
    case CanonKind::end:
    case CanonKind::digital_out:
    case CanonKind::analog_out:
    case CanonKind::wait_input: action(c); return;
    case CanonKind::traverse:
    case CanonKind::feed:
    case CanonKind::arc: move(c); return;
  }
}

void ProgramBuilder::move(const Canon& c) {
  const Vec2<double> to{c.end[0], c.end[1]};
  const bool z_change = c.end[2] != z_;
  const double z_from = z_;
  z_ = c.end[2];
  const bool feed_move = c.kind != CanonKind::traverse && (dry_run_ || torch_);
  if (z_axis_ && z_change) {
    close();
    if (first_z_line_ == 0) first_z_line_ = c.line;
    if (feed_move) {  // with the torch on: Z at rest, then the XY as a cut
      const bool xy = to != pos_ || c.kind == CanonKind::arc;  // an arc back to its start is a circle
      if (xy && ramps_++ == 0) first_ramp_line_ = c.line;
      push_z(z_, c.feed_mm_min, c.line);
      if (!xy) return;
    } else {  // torch off: Z first when it rises, XY first when it falls
      if (z_ > z_from) push_z(z_, c.kind == CanonKind::traverse ? 0 : c.feed_mm_min, c.line);
      push_xy(to, c.line);
      pos_ = to;
      if (z_ < z_from) push_z(z_, c.kind == CanonKind::traverse ? 0 : c.feed_mm_min, c.line);
      return;
    }
  } else if (!feed_move || z_change) {
    close();
    if (z_axis_) push_xy(to, c.line);
    pos_ = to;
    return;
  }
  const double feed = c.feed_mm_min * percent_ / 100.0;
  if (!open_) {
    open_ = true;
    path_start_ = out_.points.points.size();
    cur_ = ProgramPath{};
    cur_.torch = !dry_run_;
    cur_.feed_mm_min = feed;
    cur_.tol = tol_;
    cur_.pierce_delay_s = pierce_;
    cur_.before.swap(pending_);
    pending_.clear();
    add(pos_, c.line, feed);
  }
  if (c.kind == CanonKind::feed) {
    add(to, c.line, feed);
  } else {
    arc_.clear();
    sample_arc(pos_, to, {c.centre[0], c.centre[1]}, c.ccw, 0.001, arc_);
    for (const Vec2<double>& q : arc_) add(q, c.line, feed);
  }
  pos_ = to;
}

void ProgramBuilder::finish(std::map<std::string, Construct>& constructs) {
  close();
  // What follows the last path runs right after it (before the end's actions).
  if (!out_.paths.empty()) {
    std::vector<ProgramMove>& after = out_.paths.back().after;
    after.insert(after.end(), pending_.begin(), pending_.end());
  }
  pending_.clear();
  finished_ = true;
  out_.final_z = z_;
  if (!z_axis_) return;
  auto record = [&](const char* name, const char* how, std::size_t count, std::size_t line) {
    if (count == 0) return;
    Construct& c = constructs[name];
    c.handling = how;
    c.count = count;
    c.first_line = line;
  };
  record("Z move", "run as a move at rest (z axis)", out_.z_moves, first_z_line_);
  record("Z with the torch on", "ran as plunge then XY: kerf moves Z at rest (torch off, pierced again)", ramps_,
         first_ramp_line_);
}

// Without a z axis no move waits between paths: a path is final as it
// closes. With one, the last path's `after` takes the moves up to the next
// path, or, at the end, all that follow it.
bool ProgramBuilder::first_path_final() const {
  return !out_.paths.empty() && (!z_axis_ || finished_ || out_.paths.size() > 1);
}

void ProgramBuilder::take_first_path(ProgramPiece& piece) {
  io::PointFile& p = out_.points;
  const std::size_t end = out_.paths.size() > 1 ? p.path_begin[1] : open_ ? path_start_ : p.points.size();
  const auto e = static_cast<std::ptrdiff_t>(end);
  piece.path = std::move(out_.paths.front());
  piece.points.assign(p.points.begin(), p.points.begin() + e);
  piece.lines.assign(p.point_lines.begin(), p.point_lines.begin() + e);
  piece.feed.assign(out_.point_feed.begin(), out_.point_feed.begin() + e);
  out_.paths.erase(out_.paths.begin());
  p.points.erase(p.points.begin(), p.points.begin() + e);
  p.point_lines.erase(p.point_lines.begin(), p.point_lines.begin() + e);
  out_.point_feed.erase(out_.point_feed.begin(), out_.point_feed.begin() + e);
  p.path_begin.erase(p.path_begin.begin());
  for (std::size_t& b : p.path_begin) b -= end;
  if (open_) path_start_ -= end;
  ++taken_;
}

}  // namespace kerf::job
