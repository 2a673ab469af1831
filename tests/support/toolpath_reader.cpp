#include "toolpath_reader.hpp"
#include "toolpath_eval.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace kerf_test {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Word {
  char letter;
  double value;
};

// Strips comments and blanks; false with a reason for what is refused.
bool words_of(const std::string& raw, std::vector<Word>& out, std::string& why) {
  std::string s;
  int depth = 0;
  for (char c : raw) {
    if (depth > 0) {
      if (c == ')') --depth;
      continue;
    }
    if (c == '(') { ++depth; continue; }
    if (c == ';') break;
    if (c == '\r' || c == ' ' || c == '\t') continue;
    s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  out.clear();
  if (!s.empty() && s[0] == '%') return true;
  if (!s.empty() && s[0] == '/') s.erase(0, 1);  // block delete off: the line runs
  std::size_t i = 0;
  while (i < s.size()) {
    const char l = s[i];
    if (!std::isalpha(static_cast<unsigned char>(l)) && l != '$') return why = std::string("unexpected '") + l + "'", false;
    ++i;
    // [+-]digits[.digits]: no exponent (G1E1.1 is G1 then E1.1).
    const std::size_t from = i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    std::size_t digits = 0;
    while (i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i, ++digits;
    if (digits == 0) return why = std::string("no number after ") + l, false;
    out.push_back({l, std::strtod(s.substr(from, i - from).c_str(), nullptr)});
  }
  return true;
}

int code10(double v) { return static_cast<int>(std::lround(v * 10)); }

struct State {
  double unit = 1.0;  // mm per program unit
  bool relative = false;
  bool arc_absolute = false;  // G90.1
  int motion = -1;            // 0..3
  TPoint pos;                 // machine coordinates, mm
  double z = 0;               // program Z, mm (only whether it changes matters)
  bool z_since_xy = false;    // Z moved on its own since the last XY move
  TPoint work[9];             // G54..G59.3 offsets, mm
  int system = 0;
  TPoint g92;
  bool torch = false;
};

TPoint offset(const State& s) { return {s.work[s.system].x + s.g92.x, s.work[s.system].y + s.g92.y}; }

}  // namespace

Toolpath parse_toolpath(const std::string& text) {
  Toolpath t;
  State st;
  std::vector<RunLine> run;  // the lines as run: loops unrolled, values computed (toolpath_eval.hpp)
  std::string run_why;
  if (!run_program(text, run, run_why)) {
    t.error = run_why;
    return t;
  }
  std::size_t line = 0;
  std::vector<Word> words;
  auto fail = [&](const std::string& why) {
    t.ok = false;
    t.error = std::to_string(line) + ": " + why;
    return t;
  };
  for (const RunLine& rl : run) {
    line = rl.line;
    const std::string& raw = rl.text;
    std::string why;
    if (!words_of(raw, words, why)) return fail(why);
    bool has_z = false;
    double z = 0;
    bool has_x = false, has_y = false, has_i = false, has_j = false, has_r = false, has_p = false;
    double x = 0, y = 0, i = 0, j = 0, r = 0, p = 0;
    bool g53 = false, g92 = false, end = false, home = false;
    int g10 = 0;  // the L word
    int motion = st.motion;
    for (const Word& w : words) {
      switch (w.letter) {
        case 'X': has_x = true; x = w.value; break;
        case 'Z': has_z = true; z = w.value; break;
        case 'Y': has_y = true; y = w.value; break;
        case 'I': has_i = true; i = w.value; break;
        case 'J': has_j = true; j = w.value; break;
        case 'R': has_r = true; r = w.value; break;
        case 'P': has_p = true; p = w.value; break;
        case 'L': g10 = static_cast<int>(std::lround(w.value)); break;
        case 'M': {
          const int m = code10(w.value);
          if (m == 30 || m == 40) st.torch = true, t.uses_torch = true;
          if (m == 50) st.torch = false, t.uses_torch = true;
          if (m == 20 || m == 300) end = true;
          break;
        }
        case 'G': {
          const int g = code10(w.value);
          if (g == 0 || g == 10 || g == 20 || g == 30) motion = g / 10;
          else if (g == 200) st.unit = 25.4;
          else if (g == 210) st.unit = 1.0;
          else if (g == 900) st.relative = false;
          else if (g == 910) st.relative = true;
          else if (g == 901) st.arc_absolute = true;
          else if (g == 911) st.arc_absolute = false;
          else if (g == 530) g53 = true;
          else if (g >= 540 && g <= 590 && g % 10 == 0) st.system = (g - 540) / 10;
          else if (g == 591 || g == 592 || g == 593) st.system = 6 + (g - 591);
          else if (g == 920) g92 = true;
          else if (g == 921 || g == 922) st.g92 = {0, 0};
          else if (g == 280) home = true;
          else if (g == 300 || g == 923) return fail("G" + std::to_string(g / 10) + " is not read");
          else if (g == 180 || g == 190) return fail("arcs outside the XY plane");
          break;
        }
        default: break;
      }
    }
    const bool is_g10 = std::any_of(words.begin(), words.end(), [](const Word& w) { return w.letter == 'G' && code10(w.value) == 100; });
    if (is_g10) {
      // G10 L2 Pn: offset n (0: the current system) set to X Y; L20: set so
      // that the current position reads X Y in system n.
      const int n = has_p ? static_cast<int>(std::lround(p)) : 0;
      if (n < 0 || n > 9) return fail("G10 P out of range");
      TPoint& o = st.work[n == 0 ? st.system : n - 1];
      if (g10 == 2) {
        if (has_x) o.x = x * st.unit;
        if (has_y) o.y = y * st.unit;
      } else if (g10 == 20) {
        if (has_x) o.x = st.pos.x - st.g92.x - x * st.unit;
        if (has_y) o.y = st.pos.y - st.g92.y - y * st.unit;
      } else {
        return fail("G10 other than L2/L20");
      }
      continue;
    }
    if (g92) {  // the current position reads X Y from now on
      const TPoint w = st.work[st.system];
      if (has_x) st.g92.x = st.pos.x - w.x - x * st.unit;
      if (has_y) st.g92.y = st.pos.y - w.y - y * st.unit;
      continue;
    }
    if (home) {  // G28: rapid through X Y (if given) to the machine origin
      TMove m;
      m.rapid = true;
      m.start = st.pos;
      m.line = line;
      m.torch = st.torch;
      const TPoint off = offset(st);
      TPoint via = st.pos;
      if (has_x) via.x = st.relative ? st.pos.x + x * st.unit : x * st.unit + off.x;
      if (has_y) via.y = st.relative ? st.pos.y + y * st.unit : y * st.unit + off.y;
      m.end = via;
      t.moves.push_back(m);
      m.start = via;
      m.end = {0, 0};
      t.moves.push_back(m);
      st.pos = {0, 0};
      continue;
    }
    st.motion = motion;
    const double z_to = !has_z || st.motion < 0 ? st.z : st.relative ? st.z + z * st.unit : z * st.unit;
    const bool z_moves = z_to != st.z;
    st.z = z_to;
    if (!(has_x || has_y) && z_moves) st.z_since_xy = true;
    // An arc with no X or Y is a full circle (LinuxCNC: G2 I10).
    if ((has_x || has_y || (st.motion >= 2 && (has_i || has_j || has_r))) && st.motion >= 0) {
      const TPoint off = g53 ? TPoint{0, 0} : offset(st);
      TPoint to = st.pos;
      if (st.relative && !g53) {
        if (has_x) to.x += x * st.unit;
        if (has_y) to.y += y * st.unit;
      } else {
        if (has_x) to.x = x * st.unit + off.x;
        if (has_y) to.y = y * st.unit + off.y;
      }
      TMove m;
      m.rapid = st.motion == 0;
      m.start = st.pos;
      m.end = to;
      m.torch = st.torch;
      m.line = line;
      m.z_moves = z_moves;
      m.after_z = st.z_since_xy;
      st.z_since_xy = false;
      if (st.motion >= 2) {
        m.arc = true;
        m.dir = st.motion == 3 ? 1 : -1;
        if (has_r) {
          // The centre on the chord's bisector; R < 0 for the longer way round.
          const double dx = to.x - st.pos.x, dy = to.y - st.pos.y, c = std::hypot(dx, dy);
          const double rr = std::fabs(r * st.unit);
          if (!(c > 0) || c > 2 * rr + 1e-9) return fail("R arc that cannot reach its end");
          const double h = std::sqrt(std::max(0.0, rr * rr - c * c / 4));
          const double side = (m.dir > 0 ? 1 : -1) * (r < 0 ? -1 : 1);
          m.centre = {st.pos.x + dx / 2 - side * h * dy / c, st.pos.y + dy / 2 + side * h * dx / c};
        } else {
          if (!has_i && !has_j) return fail("arc with no centre");
          if (st.arc_absolute)
            m.centre = {(has_i ? i * st.unit : 0) + off.x, (has_j ? j * st.unit : 0) + off.y};
          else
            m.centre = {st.pos.x + i * st.unit, st.pos.y + j * st.unit};
        }
        const double r0 = std::hypot(m.start.x - m.centre.x, m.start.y - m.centre.y);
        const double r1 = std::hypot(m.end.x - m.centre.x, m.end.y - m.centre.y);
        if (!(r0 > 0) || std::fabs(r1 - r0) > 0.01 + 1e-4 * r0) return fail("arc end off its circle");
      }
      const bool moved = m.arc || std::hypot(to.x - st.pos.x, to.y - st.pos.y) > 0;
      if (moved) t.moves.push_back(m);
      st.pos = to;
    }
    if (end) break;
  }
  t.ok = true;
  return t;
}

Toolpath read_toolpath(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    Toolpath t;
    t.error = "0: cannot open " + path;
    return t;
  }
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_toolpath(ss.str());
}

std::vector<TMove> cut_moves(const Toolpath& t) {
  std::vector<TMove> out;
  for (const TMove& m : t.moves)
    if (!m.rapid && (m.torch || !t.uses_torch)) out.push_back(m);
  return out;
}

namespace {
double arc_sweep(const TMove& m) {
  const double a0 = std::atan2(m.start.y - m.centre.y, m.start.x - m.centre.x);
  const double a1 = std::atan2(m.end.y - m.centre.y, m.end.x - m.centre.x);
  double s = m.dir > 0 ? a1 - a0 : a0 - a1;
  while (s <= 1e-12) s += 2 * kPi;  // equal ends: a full circle
  while (s > 2 * kPi) s -= 2 * kPi;
  return s;
}
}  // namespace

double distance_to_move(const TMove& m, TPoint p) {
  if (!m.arc) {
    const double dx = m.end.x - m.start.x, dy = m.end.y - m.start.y;
    const double l2 = dx * dx + dy * dy;
    double u = l2 > 0 ? ((p.x - m.start.x) * dx + (p.y - m.start.y) * dy) / l2 : 0;
    u = std::clamp(u, 0.0, 1.0);
    return std::hypot(m.start.x + u * dx - p.x, m.start.y + u * dy - p.y);
  }
  // The arc's radius may differ at the ends (within the reader's slack): the
  // circle through the start is the path, and the end is checked on its own.
  const double r = std::hypot(m.start.x - m.centre.x, m.start.y - m.centre.y);
  const double a0 = std::atan2(m.start.y - m.centre.y, m.start.x - m.centre.x);
  const double ap = std::atan2(p.y - m.centre.y, p.x - m.centre.x);
  double u = m.dir > 0 ? ap - a0 : a0 - ap;
  while (u < 0) u += 2 * kPi;
  while (u >= 2 * kPi) u -= 2 * kPi;
  const double to_ends = std::min(std::hypot(p.x - m.start.x, p.y - m.start.y), std::hypot(p.x - m.end.x, p.y - m.end.y));
  if (u <= arc_sweep(m))
    return std::min(to_ends, std::fabs(std::hypot(p.x - m.centre.x, p.y - m.centre.y) - r));
  return to_ends;
}

MoveIndex::MoveIndex(std::vector<TMove> moves, double cell_mm) : moves_(std::move(moves)), cell_(cell_mm) {
  for (std::size_t k = 0; k < moves_.size(); ++k) {
    const TMove& m = moves_[k];
    double x0 = std::min(m.start.x, m.end.x), x1 = std::max(m.start.x, m.end.x);
    double y0 = std::min(m.start.y, m.end.y), y1 = std::max(m.start.y, m.end.y);
    if (m.arc) {
      const double r = std::hypot(m.start.x - m.centre.x, m.start.y - m.centre.y) + 0.02;
      x0 = std::min(x0, m.centre.x - r), x1 = std::max(x1, m.centre.x + r);
      y0 = std::min(y0, m.centre.y - r), y1 = std::max(y1, m.centre.y + r);
    }
    const long long i0 = static_cast<long long>(std::floor(x0 / cell_)), i1 = static_cast<long long>(std::floor(x1 / cell_));
    const long long j0 = static_cast<long long>(std::floor(y0 / cell_)), j1 = static_cast<long long>(std::floor(y1 / cell_));
    if ((i1 - i0 + 1) * (j1 - j0 + 1) > 4096) {
      big_.push_back(k);
      continue;
    }
    for (long long i = i0; i <= i1; ++i)
      for (long long j = j0; j <= j1; ++j) buckets_.push_back({key(i, j), k});
  }
  std::sort(buckets_.begin(), buckets_.end());
}

double MoveIndex::nearest(TPoint p, double reach) const {
  double best = INFINITY;
  for (std::size_t k : big_) best = std::min(best, distance_to_move(moves_[k], p));
  const long long i0 = static_cast<long long>(std::floor((p.x - reach) / cell_));
  const long long i1 = static_cast<long long>(std::floor((p.x + reach) / cell_));
  const long long j0 = static_cast<long long>(std::floor((p.y - reach) / cell_));
  const long long j1 = static_cast<long long>(std::floor((p.y + reach) / cell_));
  for (long long i = i0; i <= i1; ++i)
    for (long long j = j0; j <= j1; ++j) {
      auto it = std::lower_bound(buckets_.begin(), buckets_.end(), std::make_pair(key(i, j), std::size_t{0}));
      for (; it != buckets_.end() && it->first == key(i, j); ++it)
        best = std::min(best, distance_to_move(moves_[it->second], p));
    }
  if (best <= reach) return best;
  for (const TMove& m : moves_) best = std::min(best, distance_to_move(m, p));
  return best;
}

}  // namespace kerf_test
