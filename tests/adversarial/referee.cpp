// The adversarial set's referee: checks what `kerf fit --format json` or
// `kerf weld` printed, with the test suite's independent checkers
// (tests/support, tests/gcode/weld_checker), not with kerf's own code.
//
//   kerf_adversarial_referee vertex|band POINTS FIT.json TOL
//   kerf_adversarial_referee weld IN.nc OUT.nc TOL
//
// POINTS holds "x y" per line (what the generator wrote: no comments, no
// consecutive duplicates, one path). The printed pieces are first put back
// onto their points (see unround: at most tol / 100 of rounding, which the
// checks then allow for). Exit 0 with a one-line summary when the
// output verifies, 1 with the first problem otherwise, 2 on bad arguments.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "band_checker.hpp"
#include "verifier.hpp"
#include "weld_checker.hpp"

namespace {

bool read_text(const char* path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  text = s.str();
  return true;
}

std::vector<kerf_test::VPoint> parse_points(const std::string& text) {
  std::vector<kerf_test::VPoint> pts;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    double x = 0, y = 0;
    if (std::sscanf(line.c_str(), "%lf %lf", &x, &y) == 2) pts.push_back({x, y});
  }
  return pts;
}

// The number after `"key": ` in one JSON piece line; [a, b] pairs give both.
bool json_numbers(const std::string& line, const char* key, double* out, int count) {
  const std::string k = std::string("\"") + key + "\": ";
  const std::size_t at = line.find(k);
  if (at == std::string::npos) return false;
  const char* p = line.c_str() + at + k.size();
  if (count == 2) {
    return std::sscanf(p, "[%lf, %lf]", &out[0], &out[1]) == 2;
  }
  return std::sscanf(p, "%lf", &out[0]) == 1;
}

// kerf's JSON writes one piece per line: {"type": ..., "first": ..., ...}.
bool parse_pieces(const std::string& json, std::vector<kerf_test::VPiece>& pieces,
                  std::string& why) {
  std::istringstream in(json);
  std::string line;
  while (std::getline(in, line)) {
    if (line.find("{\"type\": ") == std::string::npos) continue;
    kerf_test::VPiece pc;
    pc.arc = line.find("\"type\": \"arc\"") != std::string::npos;
    double first = 0, last = 0, s[2], e[2], c[2] = {0, 0}, dir = 0;
    if (!json_numbers(line, "first", &first, 1) || !json_numbers(line, "last", &last, 1) ||
        !json_numbers(line, "start", s, 2) || !json_numbers(line, "end", e, 2) ||
        (pc.arc && (!json_numbers(line, "centre", c, 2) || !json_numbers(line, "dir", &dir, 1)))) {
      why = "cannot read piece line: " + line;
      return false;
    }
    pc.first = static_cast<std::size_t>(first);
    pc.last = static_cast<std::size_t>(last);
    pc.sx = s[0], pc.sy = s[1], pc.ex = e[0], pc.ey = e[1], pc.cx = c[0], pc.cy = c[1];
    pc.dir = static_cast<int>(dir);
    pieces.push_back(pc);
  }
  if (pieces.empty()) {
    why = "no pieces in the output";
    return false;
  }
  return true;
}

// kerf prints its pieces rounded (to at least tol / 1000 since
// coordinate_digits). Undoes the rounding before the exact checks, and
// returns how far it had to move anything: the ends back onto their input
// points, an arc's centre onto the bisector of its ends (what a controller
// sees as a difference of the start and end radii). Fails (returns -1 and
// says why) when that exceeds tol / 100: then the printed arc is not the
// fitted one.
double unround(const std::vector<kerf_test::VPoint>& pts, std::vector<kerf_test::VPiece>& pieces,
               double tol, std::string& why) {
  double moved = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    kerf_test::VPiece& pc = pieces[k];
    if (pc.first >= pts.size() || pc.last >= pts.size() || !(pc.first < pc.last)) continue;  // verify says why
    const kerf_test::VPoint a = pts[pc.first], b = pts[pc.last];
    moved = std::fmax(moved, std::hypot(pc.sx - a.x, pc.sy - a.y));
    moved = std::fmax(moved, std::hypot(pc.ex - b.x, pc.ey - b.y));
    if (pc.arc) {
      const double rs = std::hypot(pc.sx - pc.cx, pc.sy - pc.cy);
      const double re = std::hypot(pc.ex - pc.cx, pc.ey - pc.cy);
      moved = std::fmax(moved, std::fabs(rs - re));
      // The centre's projection onto the perpendicular bisector of a-b.
      const double mx = (a.x + b.x) / 2, my = (a.y + b.y) / 2;
      const double dx = b.x - a.x, dy = b.y - a.y, d2 = dx * dx + dy * dy;
      const double along = ((pc.cx - mx) * dx + (pc.cy - my) * dy) / d2;
      pc.cx -= along * dx;
      pc.cy -= along * dy;
    }
    pc.sx = a.x, pc.sy = a.y, pc.ex = b.x, pc.ey = b.y;
    if (moved > tol / 100) {
      why = "piece " + std::to_string(k) + ": the printed piece is " + std::to_string(moved) +
            " off the fitted one (more than tol / 100)";
      return -1;
    }
  }
  return moved;
}

// An arc must pass its points in order: walking them about the centre in
// the arc's direction (a step of more than 270 degrees is a small step
// back), the walk never leaves [0, sweep] by more than 2 tol / r and ends on
// the sweep. The checkers above measure each point against the circle (and
// the farthest one against the sweep) only, so a point path that winds
// round twice, or runs backwards, passes them. Radii within tol are skipped.
bool in_order(const std::vector<kerf_test::VPoint>& pts, const kerf_test::VPiece& pc, double tol,
              std::string& why) {
  const double two_pi = 6.283185307179586;
  const double r = std::hypot(pc.sx - pc.cx, pc.sy - pc.cy);
  if (!pc.arc || !(r > tol)) return true;
  auto at = [&](double x, double y) { return std::atan2(y - pc.cy, x - pc.cx); };
  auto wrap = [&](double a) {
    a = std::fmod(a, two_pi);
    return a < 0 ? a + two_pi : a;
  };
  const bool closed = pc.sx == pc.ex && pc.sy == pc.ey;
  const double sweep = closed ? two_pi : wrap(pc.dir * (at(pc.ex, pc.ey) - at(pc.sx, pc.sy)));
  const double slack = 2 * tol / r;
  double walked = 0, prev = at(pc.sx, pc.sy);
  for (std::size_t k = pc.first + 1; k <= pc.last; ++k) {
    const double a = at(pts[k].x, pts[k].y);
    double step = wrap(pc.dir * (a - prev));
    if (step > 0.75 * two_pi) step -= two_pi;
    walked += step;
    prev = a;
    if (walked < -slack || walked > sweep + slack) {
      why = "arc " + std::to_string(pc.first) + ".." + std::to_string(pc.last) + " reaches point " +
            std::to_string(k) + " out of order (walked " + std::to_string(walked) + " of a sweep of " +
            std::to_string(sweep) + " rad)";
      return false;
    }
  }
  if (std::fabs(walked - sweep) <= slack) return true;
  why = "arc " + std::to_string(pc.first) + ".." + std::to_string(pc.last) + " ends after walking " +
        std::to_string(walked) + " rad, its sweep is " + std::to_string(sweep);
  return false;
}

int fail(const std::string& why) {
  std::printf("referee: FAIL: %s\n", why.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s vertex|band|weld INPUT OUTPUT TOL\n", argv[0]);
    return 2;
  }
  const std::string mode = argv[1];
  std::string input, output;
  if (!read_text(argv[2], input) || !read_text(argv[3], output)) return fail("cannot read files");
  const double tol = std::strtod(argv[4], nullptr);
  if (mode == "weld") {
    const kerf_test::WeldCheck w = kerf_test::check_weld(input, output, tol);
    if (!w.ok) return fail(w.why);
    std::printf("referee: weld ok: %zu input moves, %zu output moves, max deviation %.3g\n",
                w.input_moves, w.output_moves, w.max_deviation);
    return 0;
  }
  const std::vector<kerf_test::VPoint> pts = parse_points(input);
  std::vector<kerf_test::VPiece> pieces;
  std::string why;
  if (!parse_pieces(output, pieces, why)) return fail(why);
  // Far from the origin the checkers' own arithmetic (radii from coordinates
  // of 1e12) is coarser than their 1e-9 relative limits: move everything so
  // that the first point is the origin (exact: nearby doubles subtract
  // exactly).
  std::vector<kerf_test::VPoint> moved_pts = pts;
  if (!pts.empty()) {
    const kerf_test::VPoint o = pts[0];
    for (kerf_test::VPoint& p : moved_pts) p.x -= o.x, p.y -= o.y;
    for (kerf_test::VPiece& pc : pieces) {
      pc.sx -= o.x, pc.sy -= o.y, pc.ex -= o.x, pc.ey -= o.y;
      if (pc.arc) pc.cx -= o.x, pc.cy -= o.y;
    }
  }
  const double moved = unround(moved_pts, pieces, tol, why);
  if (moved < 0) return fail(why);
  for (const kerf_test::VPiece& pc : pieces)
    if (!in_order(moved_pts, pc, tol, why)) return fail(why);
  double worst = 0;
  if (mode == "vertex") {
    const kerf_test::VerifyReport r = kerf_test::verify(moved_pts, pieces, tol + 2 * moved);
    if (!r.ok) return fail(r.why);
    for (const kerf_test::VPiece& pc : pieces) worst = std::fmax(worst, kerf_test::piece_error(moved_pts, pc));
  } else if (mode == "band") {
    // The slack: 1e-9 of the scale, as the band tests allow, a few units in
    // the last place of the coordinates (kerf computes with them where they
    // are), plus the printed output's measured rounding.
    double big = 0;
    for (const kerf_test::VPoint& p : pts) big = std::fmax(big, std::fmax(std::fabs(p.x), std::fabs(p.y)));
    const double slack = 1e-9 * kerf_test::scale_of(moved_pts) + 1e-14 * big + 2 * moved;
    const kerf_test::BandReport r = kerf_test::check_band_fit(
        moved_pts, kerf_test::symmetric_widths(pts.size(), tol), pieces, slack);
    if (!r.ok) return fail(r.why);
    worst = r.worst + tol;
  } else {
    std::fprintf(stderr, "unknown mode %s\n", mode.c_str());
    return 2;
  }
  std::printf("referee: %s ok: %zu points, %zu pieces, worst %.6g (tol %.6g, printed rounding %.3g)\n",
              mode.c_str(), pts.size(), pieces.size(), worst, tol, moved);
  return 0;
}
