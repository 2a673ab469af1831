#include "job/block_interp.hpp"
#include "job/gcode_names.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kerf::job {

namespace {

enum class Mode : std::uint8_t { none, rapid, linear, cw, ccw };

struct Modal {
  Mode motion = Mode::none;
  bool inches = false, relative = false, arc_absolute = false;
  double feed = 0;  // mm/min
  double pos[3] = {0, 0, 0};  // machine mm
  int selected_tool = 0;
};

// One block's words, by letter.
struct Words {
  bool has[26] = {};
  double v[26] = {};
  std::vector<int> g, m;  // codes in tenths, in the order written
  bool has_dollar = false;
  double dollar = 0;      // $n: the spindle (tool head) M3/M4/M5 act on
  std::size_t line = 0;
  bool any(char a) const { return has[a - 'A']; }
  double at(char a) const { return v[a - 'A']; }
  bool g_has(int c) const { return std::find(g.begin(), g.end(), c) != g.end(); }
  bool m_has(int c) const { return std::find(m.begin(), m.end(), c) != m.end(); }
};

}  // namespace

struct BlockInterp::Interp {
 public:
  Interp(const InterpSettings& s, const MachineState& st, Interpretation& out) : s_(s), out_(out) {
    out_.state = st;
    m_.pos[0] = s.start[0];
    m_.pos[1] = s.start[1];
  }

  bool run(std::size_t line, std::span<const GWord> words, std::string& why) {
    Words w;
    w.line = line;
    for (const GWord& word : words) {
      const int k = word.letter - 'A';
      if (word.letter == '$') w.has_dollar = true, w.dollar = word.value;
      else if (word.letter == 'G') w.g.push_back(code10(word.value));
      else if (word.letter == 'M') w.m.push_back(code10(word.value));
      else w.has[k] = true, w.v[k] = word.value;
    }
    if (block(w)) return true;
    why = why_;
    return false;
  }
  bool ended() const { return ended_; }
  double hal_cut_feed() const { return cut_feed_ / scale(); }

 private:
  bool refuse(std::string why) {
    why_ = std::move(why);
    return false;
  }
  void seen(const std::string& name, const char* handling, std::size_t line) {
    Construct& c = out_.constructs[name];
    if (c.count++ == 0) c.first_line = line, c.handling = handling;
  }
  void note(const std::string& text) {
    if (std::find(out_.notes.begin(), out_.notes.end(), text) == out_.notes.end()) out_.notes.push_back(text);
  }
  Canon& emit(CanonKind k, std::size_t line) {
    Canon c;
    c.kind = k;
    c.line = line;
    out_.canon.push_back(c);
    return out_.canon.back();
  }
  static bool io_number(double v) { return v >= 0 && v <= 255 && v == std::floor(v); }
  double scale() const { return m_.inches ? kMmPerInch : 1.0; }
  // The offset from program to machine coordinates on axis k.
  double offset(int k) const {
    return out_.state.g5x[out_.state.coord][k] + (out_.state.g92_on ? out_.state.g92[k] : 0.0);
  }

  // QtPlasmaC's M190 Pn: material n, the one [tools] maps n to; P-1 is the default cut feed.
  void material_change(const Words& w) {
    const int n = static_cast<int>(std::lround(w.at('P')));
    seen("M190 P (material)", "run", w.line);
    const auto mat = s_.tool_material.find(n);
    if (mat == s_.tool_material.end()) {
      if (n == -1) return void(cut_feed_ = s_.cut_feed);
      return note("M190 P" + std::to_string(n) + " (line " + std::to_string(w.line) +
                  ") maps to no material: the cut settings are kept");
    }
    if (mat->second.feed_mm_min > 0) cut_feed_ = mat->second.feed_mm_min;
    Canon& t = emit(CanonKind::tool, w.line);
    t.index = n, t.value = mat->second.pierce_delay_s;
  }

  bool check_letters(const Words& w) {
    static const char kAxes[] = "ABCUVW";
    for (const char* a = kAxes; *a; ++a)
      if (w.any(*a)) return refuse(std::string("the ") + *a + " axis is not supported (a 2-axis cutter: X Y, and Z)");
    const bool analog = w.m_has(660) || w.m_has(670) || w.m_has(680);
    if (w.any('E') && !analog) return refuse("E words (extruder) are not supported");
    // With G41/G42/G43 on the block, that G code's own reason comes first.
    const bool comp = w.g_has(410) || w.g_has(420) || w.g_has(411) || w.g_has(421) || w.g_has(430);
    for (const char a : {'D', 'H'})
      if (w.any(a) && !comp) return refuse(std::string(1, a) + " words (tool compensation) are not supported");
    return true;
  }

  // P, Q and L only where a code on the line takes them (LinuxCNC refuses the rest too).
  bool words_used(const Words& w) {
    bool user_m = false, arc = false;
    for (const int c : w.m) user_m = user_m || (c >= 1000 && c <= 1990);
    for (const int c : w.g) arc = arc || c == 20 || c == 30;
    arc = arc || (w.g.empty() && (m_.motion == Mode::cw || m_.motion == Mode::ccw));
    const bool io = w.m_has(620) || w.m_has(630) || w.m_has(640) || w.m_has(650) || w.m_has(660);
    const bool analog = w.m_has(670) || w.m_has(680);
    const struct {
      char letter;
      bool used;
    } uses[] = {{'P', io || user_m || arc || w.m_has(520) || w.g_has(40) || w.g_has(100) || w.g_has(640)},
                {'Q', w.m_has(660) || analog || user_m || w.g_has(640)},
                {'L', w.g_has(100) || w.m_has(660)}};
    for (const auto& u : uses)
      if (w.any(u.letter) && !u.used)
        return refuse(std::string(1, u.letter) + word_value(w.at(u.letter)).text +
                      ": no G or M code on this line takes " + std::string(1, u.letter));
    return true;
  }

  bool block(const Words& w) {
    if (!check_letters(w)) return false;
    if (w.has_dollar && !w.m_has(30) && !w.m_has(40) && !w.m_has(50)) return refuse("$ (a spindle select) without M3, M4 or M5");
    const std::size_t line = w.line;
    // Units first: F and lengths on this block are in the units it selects.
    for (const int c : w.g)
      if (c == 200 || c == 210) m_.inches = c == 200, seen(code_name('G', c), "recorded", line);
    if (w.any('F') && w.at('F') < 0) return refuse("F must be >= 0");
    if (w.any('T') && (w.at('T') < 0 || w.at('T') > 99999 || w.at('T') != std::floor(w.at('T'))))
      return refuse("T must be a tool number 0..99999");
    if (w.any('F')) {
      m_.feed = w.at('F') * scale();
      seen("F", "run", line);
    }
    if (w.any('S')) seen("S", "recorded", line);
    if (w.any('T')) {
      m_.selected_tool = static_cast<int>(std::lround(w.at('T')));
      seen("T", "run", line);
    }
    // M codes in LinuxCNC's order: M6, M3/4/5, M7/8/9, user and I/O M-codes.
    for (const int c : w.m)
      if (!m_code(c, w)) return false;
    // G codes: dwell, modes, offsets, then motion.
    bool motion_word = false, g53 = false, non_motion_axes = false;
    for (const int c : w.g) {
      const std::string name = code_name('G', c);
      switch (c) {
        case 0: case 10: case 20: case 30:
          m_.motion = c == 0 ? Mode::rapid : c == 10 ? Mode::linear : c == 20 ? Mode::cw : Mode::ccw;
          motion_word = true;
          seen(name, "run", line);
          break;
        case 40:
          if (!w.any('P')) return refuse("G4 needs P (seconds)");
          if (w.at('P') < 0) return refuse("G4 P must be >= 0");
          emit(CanonKind::dwell, line).value = w.at('P');
          seen(name, "run", line);
          break;
        case 170: case 400: case 490: case 800: case 940: case 610: case 611: case 970:
          seen(name, "recorded", line);
          break;
        case 430:  // a tool length offset moves only Z, which kerf does not drive
          seen(w.any('H') ? "G43 H" : "G43", "recorded", line);
          break;
        case 180: case 190: return refuse(name + ": only the XY plane (G17) is supported");
        case 410: case 420: case 411: case 421:
          return refuse(name + ": cutter compensation is not supported (kerf compensation does not exist yet)");
        case 930: return refuse("G93: inverse time feed is not supported");
        case 950: return refuse("G95: feed per revolution is not supported");
        case 200: case 210: break;  // done above
        case 640: {
          // P: the path tolerance; Q: LinuxCNC's naive-CAM tolerance (collinear
          // moves within Q merge into one). kerf's fit does both at once, so
          // the path's tolerance is the least of P, Q and fit.tol (0: no bound).
          seen(w.any('P') ? "G64 P" : "G64", "recorded", line);
          if (w.any('Q')) seen("G64 Q", "run", line);
          double tol = s_.fit_tol;
          for (const char k : {'P', 'Q'}) {
            if (!w.any(k)) continue;
            const double v = w.at(k) * scale();
            if (v < 0) return refuse(std::string("G64 ") + k + " must be >= 0");
            if (v > 0) tol = std::min(tol, v);
          }
          if (w.any('P') || w.any('Q')) emit(CanonKind::tolerance, line).value = tol;
          break;
        }
        case 900: case 910: m_.relative = c == 910, seen(name, "recorded", line); break;
        case 901: case 911: m_.arc_absolute = c == 901, seen(name, "recorded", line); break;
        case 540: case 550: case 560: case 570: case 580: case 590: case 591: case 592: case 593:
          out_.state.coord = c < 591 ? (c - 540) / 10 : 6 + (c - 591);
          seen(name, "run", line);
          break;
        case 100:
          if (!g10(w)) return false;
          non_motion_axes = true;
          seen(name + (w.at('L') == 2 ? " L2" : " L20"), "run", line);
          break;
        case 530: g53 = true, seen(name, "run", line); break;
        case 920: case 921: case 922: case 923:
          if (!g92(c, w)) return false;
          non_motion_axes = non_motion_axes || c == 920;
          seen(name, "run", line);
          break;
        default:
          return refuse(name + " is not supported");
      }
    }
    if (!words_used(w)) return false;  // after the codes: an unsupported code is named first
    const bool axes = w.any('X') || w.any('Y') || w.any('Z') || w.any('I') || w.any('J') || w.any('R');
    if (w.any('K')) return refuse("K: arcs are in the XY plane (I J) only");
    if (axes && !non_motion_axes) {
      if (m_.motion == Mode::none) return refuse("axis words with no motion mode (G0, G1, G2 or G3)");
      if (!move(w, g53)) return false;
    } else if (g53 && !axes) {
      return refuse("G53 without a move");
    }
    (void)motion_word;
    for (const int c : w.m)
      if (c == 0 || c == 10) {
        emit(CanonKind::pause, line).index = c / 10;
        seen(code_name('M', c), "run", line);
      } else if (c == 20 || c == 300) {
        emit(CanonKind::end, line);
        seen(code_name('M', c), "run", line);
        out_.state.coord = 0;  // LinuxCNC: program end selects G54
        ended_ = true;
      }
    return true;
  }

  bool m_code(int c, const Words& w) {
    const std::size_t line = w.line;
    const std::string name = code_name('M', c);
    if (c == 0 || c == 10 || c == 20 || c == 300) return true;  // after the motion
    if (c == 520) return seen(w.any('P') ? "M52 P (adaptive feed)" : "M52", "recorded", line), true;
    if (c == 1900 && w.any('P') && s_.mcodes.count(190) == 0) return material_change(w), true;
    if (c == 60) {
      Canon& t = emit(CanonKind::tool, line);
      t.index = m_.selected_tool;
      t.value = -1;
      seen(name, "run", line);
      const auto mat = s_.tool_material.find(m_.selected_tool);
      if (mat != s_.tool_material.end()) t.value = mat->second.pierce_delay_s;
      if (mat != s_.tool_material.end()) {
        if (mat->second.feed_mm_min > 0) m_.feed = cut_feed_ = mat->second.feed_mm_min;
      } else if (!noted_tool_[m_.selected_tool]) {
        noted_tool_[m_.selected_tool] = true;
        char buf[96];
        std::snprintf(buf, sizeof buf, "T%d (line %zu) maps to no material: the cut settings are kept",
                      m_.selected_tool, line);
        note(buf);
      }
      return true;
    }
    if (c == 30 || c == 40 || c == 50) {
      // $0 is the torch (QtPlasmaC); $-1 (all) only to switch off.
      if (w.has_dollar && w.dollar != 0 && !(c == 50 && w.dollar == -1))
        return refuse(name + " $" + std::string(word_value(w.dollar)) +
                      ": only one tool head ($0, the torch) is supported (QtPlasmaC's scribe and spot are not)");
      emit(CanonKind::torch, line).index = c != 50;
      seen(w.has_dollar ? name + " $" : name, "run", line);
      return true;
    }
    if (c == 70 || c == 80 || c == 90) {
      const int outs[2] = {s_.mist_output, s_.flood_output};
      bool any = false;
      for (int i = 0; i < 2; ++i) {
        if (outs[i] < 0 || (c == 70 && i == 1) || (c == 80 && i == 0)) continue;
        Canon& o = emit(CanonKind::digital_out, line);
        o.index = outs[i];
        o.value = c != 90;
        any = true;
      }
      seen(name, any ? "run" : "ignored", line);
      return true;
    }
    if (c >= 620 && c <= 650) {
      if (!w.any('P')) return refuse(name + " needs P (the output number)");
      if (!io_number(w.at('P'))) return refuse(name + " P must be an output number 0..255");
      const int p = static_cast<int>(std::lround(w.at('P')));
      const bool on = c == 620 || c == 640;
      if (p == s_.torch_output) {
        emit(CanonKind::torch, line).index = on;
      } else {
        Canon& o = emit(CanonKind::digital_out, line);
        o.index = p;
        o.value = on;
        o.sync = c <= 630;
      }
      seen(name, "run", line);
      return true;
    }
    if (c == 660) {
      const double lv = w.any('L') ? w.at('L') : 0;
      if (!(lv >= 0 && lv <= 4 && lv == std::floor(lv)))
        return refuse("M66 L must be 0..4, got " + std::string(word_value(lv)));
      const int l = static_cast<int>(lv);
      if (w.any('E')) {
        if (l != 0) return refuse("M66 E (analog input) supports only L0");
        if (!io_number(w.at('E'))) return refuse("M66 E must be an input number 0..255");
        out_.analog_inputs.emplace(static_cast<int>(std::lround(w.at('E'))), line);
        seen("M66 E", "ignored", line);
        return true;
      }
      if (!w.any('P')) return refuse("M66 needs P (a digital input) or E (an analog input)");
      if (!io_number(w.at('P'))) return refuse("M66 P must be an input number 0..255");
      if (w.any('Q') && !(w.at('Q') >= 0)) return refuse("M66 Q (the timeout) must be >= 0");
      if (l != 0 && !w.any('Q')) return refuse("M66 L" + std::to_string(l) + " needs Q (the timeout in s)");
      Canon& o = emit(CanonKind::wait_input, line);
      o.index = static_cast<int>(std::lround(w.at('P')));
      o.mode = l;
      o.value = w.any('Q') ? w.at('Q') : 0;
      seen("M66 L" + std::to_string(l), "run", line);
      return true;
    }
    if (c == 670 || c == 680) {
      if (!w.any('E') || !w.any('Q')) return refuse(name + " needs E (the output) and Q (the value)");
      if (!io_number(w.at('E'))) return refuse(name + " E must be an output number 0..255");
      const int e = static_cast<int>(std::lround(w.at('E')));
      if (c == 670 && e == 3) {  // QtPlasmaC: velocity as a % of the programmed feed
        double q = w.at('Q');
        if (q <= 0 || q > 100) q = 100;  // QtPlasmaC: 0 (or over 100) restores full feed
        if (q < 10) q = 10;              // and 10 % is its floor
        emit(CanonKind::feed_percent, line).value = q;
        seen("M67 E3 (feed %)", "run", line);
        return true;
      }
      Canon& o = emit(CanonKind::analog_out, line);
      o.index = e;
      o.value = w.at('Q');
      o.sync = c == 670;
      seen(name, "run", line);
      return true;
    }
    if (c >= 1000 && c <= 1990 && c % 10 == 0) {
      const int n = c / 10;
      const auto it = s_.mcodes.find(n);
      if (it == s_.mcodes.end()) {
        if (s_.strict_mcodes)
          return refuse(name + " is a user M-code with no action: add [mcodes." + name +
                        "] with action = \"on\", \"off\", \"dwell\" or \"ignore\" to the configuration");
        if (out_.constructs.count(name) == 0)  // logged once per M-code
          note(name + " (line " + std::to_string(line) + ") has no configured action: ignored");
        seen(name, "ignored", line);
        return true;
      }
      const UserMcode& u = it->second;
      if (u.action == UserMcode::Action::dwell) {
        emit(CanonKind::dwell, line).value = u.seconds;
      } else if (u.action != UserMcode::Action::ignore) {
        Canon& o = emit(CanonKind::digital_out, line);
        o.index = u.output;
        o.value = u.action == UserMcode::Action::on;
      }
      seen(name, u.action == UserMcode::Action::ignore ? "ignored" : "run", line);
      return true;
    }
    return refuse(name + " is not supported");
  }

  // G10 L2 Pn: system n's offset is the given values; L20: the offset that
  // makes the current point have the given coordinates in system n.
  bool g10(const Words& w) {
    if (!w.any('L')) return refuse("G10 needs L (L2 or L20)");
    const double lv = w.at('L');
    if (lv != 2 && lv != 20) return refuse("G10 L" + std::string(word_value(lv)) + " is not supported (L2 and L20 are)");
    const int l = static_cast<int>(lv);
    if (!w.any('P')) return refuse("G10 L" + std::to_string(l) + " needs P (0 current, 1..9 G54..G59.3)");
    const double pv = w.at('P');
    const int p = static_cast<int>(std::lround(pv));
    if (pv != p || p < 0 || p > kCoordSystems) return refuse("G10 P must be 0..9");
    if (w.any('R')) return refuse("G10 R (rotation) is not supported");
    const int sys = p == 0 ? out_.state.coord : p - 1;
    for (int k = 0; k < 3; ++k) {
      const char a = static_cast<char>('X' + k);
      if (!w.any(a)) continue;
      const double v = w.at(a) * scale();
      if (l == 2) out_.state.g5x[sys][k] = v;
      else out_.state.g5x[sys][k] = m_.pos[k] - (out_.state.g92_on ? out_.state.g92[k] : 0.0) - v;
    }
    return true;
  }

  bool g92(int c, const Words& w) {
    MachineState& s = out_.state;
    if (c == 920) {
      if (!w.any('X') && !w.any('Y') && !w.any('Z')) return refuse("G92 needs an axis word");
      if (!s.g92_on) std::fill(std::begin(s.g92), std::end(s.g92), 0.0);
      for (int k = 0; k < 3; ++k) {
        const char a = static_cast<char>('X' + k);
        if (w.any(a)) s.g92[k] = m_.pos[k] - s.g5x[s.coord][k] - w.at(a) * scale();
      }
      s.g92_on = true;
    } else if (c == 921) {
      std::fill(std::begin(s.g92), std::end(s.g92), 0.0);
      s.g92_on = false;
    } else if (c == 922) {
      s.g92_on = false;
    } else {
      s.g92_on = true;
    }
    return true;
  }

  bool move(const Words& w, bool g53) {
    const std::size_t line = w.line;
    const bool arc = m_.motion == Mode::cw || m_.motion == Mode::ccw;
    if (g53 && (arc || m_.relative)) return refuse("G53 needs G0 or G1 in absolute mode (G90)");
    double start[3], end[3];
    for (int k = 0; k < 3; ++k) {
      start[k] = end[k] = m_.pos[k];
      const char a = static_cast<char>('X' + k);
      if (!w.any(a)) continue;
      const double v = w.at(a) * scale();
      end[k] = g53 ? v : m_.relative ? m_.pos[k] + v : v + offset(k);
    }
    Canon c;
    c.line = line;
    std::copy(end, end + 3, c.end);
    c.feed_mm_min = m_.feed;
    if (!arc) {
      if (w.any('I') || w.any('J') || w.any('R')) return refuse("I, J or R on a move that is not an arc");
      c.kind = m_.motion == Mode::rapid ? CanonKind::traverse : CanonKind::feed;
    } else {
      c.kind = CanonKind::arc;
      c.ccw = m_.motion == Mode::ccw;
      if (!arc_centre(w, start, end, c)) return false;
    }
    out_.canon.push_back(c);
    std::copy(end, end + 3, m_.pos);
    return true;
  }

  bool arc_centre(const Words& w, const double* start, const double* end, Canon& c) {
    const bool ij = w.any('I') || w.any('J'), r = w.any('R');
    if (ij == r) return refuse(r ? "an arc with both R and I/J" : "an arc without I J or R");
    if (w.any('P') && w.at('P') != 1) return refuse("an arc with P (turns) other than 1 is not supported");
    if (ij) {
      const double i = w.any('I') ? w.at('I') * scale() : 0, j = w.any('J') ? w.at('J') * scale() : 0;
      c.centre[0] = m_.arc_absolute ? i + offset(0) : start[0] + i;
      c.centre[1] = m_.arc_absolute ? j + offset(1) : start[1] + j;
      const double r0 = std::hypot(start[0] - c.centre[0], start[1] - c.centre[1]);
      const double r1 = std::hypot(end[0] - c.centre[0], end[1] - c.centre[1]);
      if (!(r0 > 0)) return refuse("an arc with its centre on its start point");
      if (std::fabs(r1 - r0) > 0.01 + 1e-4 * r0) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "the arc's end is off its circle: radius %.6g at the start, %.6g at the end",
                      r0 / scale(), r1 / scale());  // in the program's units
        return refuse(buf);
      }
      return true;
    }
    const double rr = w.at('R') * scale();
    const double dx = end[0] - start[0], dy = end[1] - start[1];
    const double d = std::hypot(dx, dy);
    if (d == 0) return refuse("an R arc needs an end point away from its start");
    double h2 = rr * rr - d * d / 4;
    if (h2 < 0) {
      if (d / 2 - std::fabs(rr) > 1e-6 * (1 + std::fabs(rr)))
        return refuse("R is smaller than half the distance to the end point");
      h2 = 0;
    }
    double h = std::sqrt(h2) / d;
    if (!c.ccw != (rr < 0)) h = -h;
    c.centre[0] = start[0] + dx / 2 - h * dy;
    c.centre[1] = start[1] + dy / 2 + h * dx;
    return true;
  }

  const InterpSettings& s_;
  Interpretation& out_;
  Modal m_;
  std::string why_;
  bool ended_ = false;
  std::map<int, bool> noted_tool_;  // unmapped tools already noted
  double cut_feed_ = s_.cut_feed;    // mm/min: the material's, else [cut] feed
};

BlockInterp::BlockInterp(const InterpSettings& settings, const MachineState& state, Interpretation& out)
    : impl_(std::make_unique<Interp>(settings, state, out)) {}
BlockInterp::~BlockInterp() = default;
bool BlockInterp::run(std::size_t line, std::span<const GWord> words, std::string& why) {
  return impl_->run(line, words, why);
}
bool BlockInterp::ended() const { return impl_->ended(); }
double BlockInterp::hal_cut_feed() const { return impl_->hal_cut_feed(); }

}  // namespace kerf::job
