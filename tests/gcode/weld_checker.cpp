#include "weld_checker.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <vector>

namespace kerf_test {

namespace {

struct Pt {
  double x = 0, y = 0;
};
Pt operator-(Pt a, Pt b) { return {a.x - b.x, a.y - b.y}; }
Pt operator+(Pt a, Pt b) { return {a.x + b.x, a.y + b.y}; }
double len(Pt a) { return std::hypot(a.x, a.y); }

double seg_dist(Pt a, Pt b, Pt p) {
  const Pt d = b - a, q = p - a;
  const double l2 = d.x * d.x + d.y * d.y;
  double t = l2 > 0 ? (q.x * d.x + q.y * d.y) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return len(p - Pt{a.x + t * d.x, a.y + t * d.y});
}

struct Line {
  std::size_t number = 0;
  std::string text;
  std::map<char, double> words;  // last value per letter, except G
  std::vector<int> g;            // G codes x10
  std::string comments;          // all comment text, in order
  bool has_words = false;
};

std::vector<Line> split(const std::string& s) {
  std::vector<Line> out;
  std::size_t i = 0;
  while (i < s.size()) {
    std::size_t j = s.find_first_of("\r\n", i);
    if (j == std::string::npos) j = s.size();
    Line l;
    l.number = out.size() + 1;
    l.text = s.substr(i, j - i);
    i = j;
    if (i < s.size()) i += (s[i] == '\r' && i + 1 < s.size() && s[i + 1] == '\n') ? 2 : 1;
    std::string code;
    for (std::size_t k = 0; k < l.text.size(); ++k) {
      const char c = l.text[k];
      if (c == ';') { l.comments += l.text.substr(k + 1); break; }
      if (c == '(') {
        const std::size_t e = l.text.find(')', k);
        l.comments += l.text.substr(k + 1, e - k - 1);
        k = e;
        continue;
      }
      if (c != ' ' && c != '\t') code += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    for (std::size_t k = 0; k < code.size();) {
      const char letter = code[k++];
      // Plain decimals only: strtod would read "Y1E5" as one number.
      std::size_t e = k;
      if (e < code.size() && (code[e] == '+' || code[e] == '-')) ++e;
      while (e < code.size() && (std::isdigit(static_cast<unsigned char>(code[e])) != 0 || code[e] == '.')) ++e;
      const double v = std::strtod(code.substr(k, e - k).c_str(), nullptr);
      k = e;
      if (letter == 'G') l.g.push_back(static_cast<int>(std::lround(v * 10)));
      else l.words[letter] = v;
      l.has_words = true;
    }
    out.push_back(l);
  }
  return out;
}

// A move of the XY path: a line (arc = 0) or an arc (+1 CCW, -1 CW).
struct Move {
  Pt a, b, c;
  int arc = 0;
  std::size_t line = 0;
};

struct Walker {
  int motion = -1;
  Pt pos;
  bool relative = false;
  // Is the line an XY feed move? Fills `m` and advances the position.
  bool feed_move(const Line& l, Move& m, bool lines_only) {
    int mo = motion;
    bool other_g = false;
    for (int g : l.g) {
      if (g == 0 || g == 10 || g == 20 || g == 30) mo = g / 10;
      else other_g = true;
      if (g == 900) relative = false;
      if (g == 910) relative = true;
    }
    bool only_xy = !other_g && !l.words.empty();
    bool has_xy = false;
    for (const auto& [k, v] : l.words) {
      if (k == 'X' || k == 'Y') has_xy = true;
      else if (k != 'N' && k != 'F' && k != 'I' && k != 'J') only_xy = false;
    }
    motion = mo;
    Pt to = pos;
    auto x = l.words.find('X'), y = l.words.find('Y');
    if (x != l.words.end()) to.x = relative ? pos.x + x->second : x->second;
    if (y != l.words.end()) to.y = relative ? pos.y + y->second : y->second;
    const bool is_move = only_xy && has_xy && mo >= 1 && mo <= (lines_only ? 1 : 3);
    if (is_move) {
      m = {pos, to, {}, mo == 1 ? 0 : (mo == 3 ? 1 : -1), l.number};
      if (mo != 1) {
        const auto i = l.words.find('I'), j = l.words.find('J');
        m.c = pos + Pt{i == l.words.end() ? 0 : i->second, j == l.words.end() ? 0 : j->second};
      }
    }
    if (x != l.words.end() || y != l.words.end()) pos = to;
    return is_move;
  }
};

Pt arc_point(const Move& m, double t, double& widen) {
  if (m.arc == 0) return {m.a.x + t * (m.b.x - m.a.x), m.a.y + t * (m.b.y - m.a.y)};
  const double r = len(m.a - m.c);
  widen = std::fabs(r - len(m.b - m.c));
  const double a0 = std::atan2(m.a.y - m.c.y, m.a.x - m.c.x);
  const double a1 = std::atan2(m.b.y - m.c.y, m.b.x - m.c.x);
  double sweep = m.arc > 0 ? a1 - a0 : a0 - a1;
  if (sweep <= 0) sweep += 2 * M_PI;
  const double ang = a0 + m.arc * sweep * t;
  return {m.c.x + r * std::cos(ang), m.c.y + r * std::sin(ang)};
}

double move_length(const Move& m) {
  if (m.arc == 0) return len(m.b - m.a);
  double w = 0;
  double l = 0;
  Pt prev = m.a;
  for (int k = 1; k <= 16; ++k) {
    const Pt q = arc_point(m, k / 16.0, w);
    l += len(q - prev);
    prev = q;
  }
  return l * 1.01;
}

// Distance from p to a drawn move (dense sampling is not enough near a
// vertex, so arcs use the exact circle when p is within the sweep).
double move_dist(const Move& m, Pt p) {
  if (m.arc == 0) return seg_dist(m.a, m.b, p);
  const double r = len(m.a - m.c);
  const double widen = std::fabs(r - len(m.b - m.c));
  const double a0 = std::atan2(m.a.y - m.c.y, m.a.x - m.c.x);
  const double a1 = std::atan2(m.b.y - m.c.y, m.b.x - m.c.x);
  const double ap = std::atan2(p.y - m.c.y, p.x - m.c.x);
  auto ccw_from = [](double from, double to) {
    double d = to - from;
    while (d < 0) d += 2 * M_PI;
    while (d >= 2 * M_PI) d -= 2 * M_PI;
    return d;
  };
  double sweep = m.arc > 0 ? ccw_from(a0, a1) : ccw_from(a1, a0);
  if (sweep == 0) sweep = 2 * M_PI;
  const double at = m.arc > 0 ? ccw_from(a0, ap) : ccw_from(ap, a0);
  const double end_d = std::min(len(p - m.a), len(p - m.b));
  if (at <= sweep) return std::min(end_d, std::fabs(len(p - m.c) - r) + widen);
  return end_d + widen;
}

// A kept line: the same text, or with "G1" inserted.
bool same_kept(const std::string& a, const std::string& b) {
  if (a == b) return true;
  for (const char* ins : {" G1", "G1 "}) {
    const std::size_t p = b.find(ins);
    if (p != std::string::npos && b.substr(0, p) + b.substr(p + 3) == a) return true;
  }
  return false;
}

// The polyline's segments by grid cell: each segment is listed in every cell
// within one cell of a point on it, and cells are at least 2 tol wide, so a
// point's own cell lists every segment within tol of it.
struct Grid {
  double cs = 1;
  std::map<std::pair<long, long>, std::vector<std::size_t>> cells;
  std::pair<long, long> key(Pt p) const {
    return {static_cast<long>(std::floor(p.x / cs)), static_cast<long>(std::floor(p.y / cs))};
  }
  Grid(const std::vector<Pt>& poly, double tol) {
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (const Pt& p : poly) {
      lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
      lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
    }
    cs = std::max(2 * tol, std::max(hi_x - lo_x, hi_y - lo_y) / 256);
    for (std::size_t s = 0; s + 1 < poly.size(); ++s) {
      const int n = 1 + static_cast<int>(std::ceil(2 * len(poly[s + 1] - poly[s]) / cs));
      for (int k = 0; k <= n; ++k) {
        const double t = static_cast<double>(k) / n;
        const auto c = key({poly[s].x + t * (poly[s + 1].x - poly[s].x), poly[s].y + t * (poly[s + 1].y - poly[s].y)});
        for (long dx = -1; dx <= 1; ++dx)
          for (long dy = -1; dy <= 1; ++dy) {
            std::vector<std::size_t>& v = cells[{c.first + dx, c.second + dy}];
            if (v.empty() || v.back() != s) v.push_back(s);
          }
      }
    }
  }
};

}  // namespace

WeldCheck check_weld(const std::string& input, const std::string& output, double tol) {
  WeldCheck r;
  const std::vector<Line> in = split(input), out = split(output);
  Walker wi, wo;
  std::size_t i = 0, o = 0;
  std::string in_comments, out_comments;
  auto fail = [&](std::size_t line, const std::string& why) {
    r.ok = false;
    r.why = "output line " + std::to_string(line) + ": " + why;
    return r;
  };
  while (true) {
    // One group: the feed moves up to the next line of another kind.
    std::vector<Pt> poly{wi.pos};
    const Pt out_start = wo.pos;
    std::vector<Move> moves;
    Move m;
    for (; i < in.size(); ++i) {
      if (!in[i].has_words) { in_comments += in[i].comments; continue; }
      Walker save = wi;
      if (!wi.feed_move(in[i], m, true)) { wi = save; break; }
      in_comments += in[i].comments;
      poly.push_back(m.b);
      ++r.input_moves;
    }
    for (; o < out.size(); ++o) {
      if (!out[o].has_words) { out_comments += out[o].comments; continue; }
      if (i < in.size() && same_kept(in[i].text, out[o].text)) break;  // an input arc, kept
      Walker save = wo;
      if (!wo.feed_move(out[o], m, false)) { wo = save; break; }
      out_comments += out[o].comments;
      moves.push_back(m);
      ++r.output_moves;
    }
    const std::size_t at = o < out.size() ? out[o].number : out.size();
    if (len(out_start - poly.front()) > 1e-9 + tol) return fail(at, "the group starts away from the input");
    if (moves.empty() != (poly.size() == 1)) return fail(at, "moves appear or vanish");
    if (!moves.empty()) {
      if (len(moves.back().b - poly.back()) > tol * (1 + 1e-9))
        return fail(moves.back().line, "ends away from the input's end");
      for (std::size_t k = 1; k < moves.size(); ++k)
        if (len(moves[k].a - moves[k - 1].b) > 1e-12) return fail(moves[k].line, "moves do not chain");
      for (const Pt& p : poly) {
        double best = 1e300;
        for (const Move& mv : moves) best = std::min(best, move_dist(mv, p));
        r.max_deviation = std::max(r.max_deviation, best);
        if (best > tol * (1 + 1e-9)) return fail(at, "an input vertex is " + std::to_string(best) + " from the output");
      }
      const Grid grid(poly, tol);
      for (const Move& mv : moves) {
        const double l = move_length(mv);
        const int n = std::clamp(static_cast<int>(std::ceil(4 * l / tol)), 2, 20000);
        for (int k = 0; k <= n; ++k) {
          double widen = 0;
          const Pt q = arc_point(mv, static_cast<double>(k) / n, widen);
          double best = 1e300;
          if (const auto c = grid.cells.find(grid.key(q)); c != grid.cells.end())
            for (std::size_t s : c->second) best = std::min(best, seg_dist(poly[s], poly[s + 1], q));
          if (best > tol)  // not near its cell's segments: measure against all of them
            for (std::size_t s = 0; s + 1 < poly.size(); ++s) best = std::min(best, seg_dist(poly[s], poly[s + 1], q));
          if (poly.size() == 1) best = len(q - poly[0]);
          best += widen;
          r.max_deviation = std::max(r.max_deviation, best);
          // The sample q itself carries rounding (a few ulps of its coordinates,
          // more where the compiler fuses a*t+b, as aarch64 does): at a tol of
          // 1e-300 that alone would "leave the band".
          const double rounding = 1e-14 * (1 + std::fabs(q.x) + std::fabs(q.y));
          if (best > tol * (1 + 1e-9) + rounding)
            return fail(mv.line, "the output leaves the band by " + std::to_string(best - tol));
        }
      }
    }
    if (i >= in.size() || o >= out.size()) {
      if (i < in.size() || o < out.size()) return fail(at, "the files end differently");
      break;
    }
    // The unchanged line.
    const std::string& a = in[i].text;
    const std::string& b = out[o].text;
    if (!same_kept(a, b)) return fail(out[o].number, "changed: \"" + a + "\" became \"" + b + "\"");
    in_comments += in[i].comments;
    out_comments += out[o].comments;
    wi.feed_move(in[i], m, true);
    wo.feed_move(out[o], m, false);
    ++i;
    ++o;
  }
  if (in_comments != out_comments) return fail(0, "the comments differ");
  r.ok = true;
  return r;
}

}  // namespace kerf_test
