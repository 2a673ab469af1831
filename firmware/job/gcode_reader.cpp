#include "job/gcode_reader.hpp"

#include "io/input_file.hpp"
#include "io/prefault.hpp"
#include "job/gcode_expr.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace kerf::job {

static_assert(sizeof(GWord) <= 16, "a word is written for every letter of a file");

namespace {

using State = GcodeModal;

// One block's words, comments and unknown words while it is parsed; reused
// from block to block, then appended to the file's Source.
struct Scratch {
  std::vector<GWord> words;
  std::vector<std::string_view> comments;
  std::vector<std::string_view> unknown;
};

bool fail(GcodeFile& f, std::size_t line, std::string reason) {
  f.ok = false;
  f.line = line;
  f.reason = std::move(reason);
  return false;
}

// ASCII only, inline: <cctype>'s calls (and their locale) were a tenth of
// the read.
bool is_blank(char c) { return c == ' ' || c == '\t'; }
bool is_digit(char c) { return static_cast<unsigned char>(c - '0') < 10; }
bool is_alpha(char c) { return static_cast<unsigned char>((c | 0x20) - 'a') < 26; }

// The number of a word (sign, digits, at most one point): from_chars is
// correctly rounded like strtod and several times faster; strtod takes what
// it refuses (a '+', or a magnitude out of double's range).
double parse_number(const std::string& number) {
  double v = 0;
  const char* first = number.data();
  const char* last = first + number.size();
  const std::from_chars_result r = std::from_chars(first, last, v);
  if (r.ec == std::errc() && r.ptr == last) return v;
  return std::strtod(number.c_str(), nullptr);
}

// A word's number as scanned: its digits as an integer while they fit.
struct Number {
  std::uint64_t mantissa = 0;
  std::size_t digits = 0;       // all of them, leading zeros included
  std::size_t after_point = 0;  // digits after the point
  bool negative = false;
};

// The value of a scanned number, correctly rounded without a parse when the
// digits fit in 53 bits and at most 22 follow the point: both the integer
// and the power of ten are then exact doubles, and one division rounds
// once (the usual fast path of decimal conversion). False otherwise.
bool exact_value(const Number& n, double& v) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                      1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  if (n.digits > 19 || n.mantissa > (std::uint64_t{1} << 53) || n.after_point > 22) return false;
  v = static_cast<double>(n.mantissa) / kPow10[n.after_point];
  if (n.negative) v = -v;
  return true;
}

// Splits the words and comments of one line; false with a reason on a form
// kerf refuses to guess at.
bool split_words(GBlock& b, Scratch& sc, std::string& reason) {
  const std::string_view s = b.text;
  std::size_t i = 0;
  while (i < s.size() && is_blank(s[i])) ++i;
  if (i < s.size() && s[i] == '/') return reason = "block delete (/) is not supported", false;
  if (s.find_first_not_of(" \t", i) != std::string::npos && s[i] == '%' &&
      s.find_first_not_of(" \t", i + 1) == std::string::npos)
    return true;  // the tape mark
  const char* rest = s.data() + i;  // a parameter or an expression anywhere? (most lines: neither, two memchr)
  const bool maybe = std::memchr(rest, '#', s.size() - i) != nullptr || std::memchr(rest, '[', s.size() - i) != nullptr;
  for (std::size_t k = i; maybe && k < s.size() && s[k] != ';'; ++k) {
    if (s[k] == '(') k = std::min(s.find(')', k), s.size() - 1);
    else if (s[k] == '#' || s[k] == '[') return b.dynamic = true, true;
  }
  while (i < s.size()) {
    const char c = s[i];
    if (is_blank(c)) {
      ++i;
    } else if (c == ';') {
      sc.comments.push_back(s.substr(i));
      break;
    } else if (c == '(') {
      const std::size_t close = s.find(')', i);
      if (close == std::string::npos) return reason = "unclosed ( comment", false;
      sc.comments.push_back(s.substr(i, close + 1 - i));
      i = close + 1;
    } else if (c == '#' || c == '[') {
      b.dynamic = true;
      return true;
    } else if (is_alpha(c) || c == '$') {  // '$': LinuxCNC's spindle (QtPlasmaC's tool head) select
      const char letter = c == '$' ? '$' : static_cast<char>(c & ~0x20);
      if (letter == 'O') return b.dynamic = true, true;
      std::size_t j = i + 1;
      while (j < s.size() && is_blank(s[j])) ++j;
      const std::size_t number_at = j;
      Number num;
      if (j < s.size() && (s[j] == '+' || s[j] == '-')) num.negative = s[j++] == '-';
      bool point = false;
      while (j < s.size()) {
        const char d = s[j];
        if (is_digit(d)) {
          if (num.digits < 19) num.mantissa = num.mantissa * 10 + static_cast<unsigned>(d - '0');
          ++num.digits;
          if (point) ++num.after_point;
        } else if (d == '.' && !point) {
          point = true;
        } else if (!is_blank(d)) {
          break;
        }
        ++j;
      }
      if (num.digits == 0) {
        const std::size_t next = s.find_first_not_of(" \t", i + 1);
        if (next != std::string::npos && (s[next] == '#' || s[next] == '[')) return b.dynamic = true, true;
        if (next != std::string::npos && (s[next] == '-' || s[next] == '+')) {
          const std::size_t after = s.find_first_not_of(" \t", next + 1);
          if (after != std::string::npos && (s[after] == '#' || s[after] == '[')) return b.dynamic = true, true;
        }
        std::string word(1, c);
        // Letters run together ("ATAN", "XYZ") are a name; a letter, blanks and
        // the next word ("G1 X Y1") is a word whose number is missing.
        if (i + 1 < s.size() && is_alpha(s[i + 1]))
          return reason = "not a word: \"" + std::string(s.substr(i, s.find_first_of(" \t;(", i) - i)) +
                          "\" (macros and named functions are not supported)", false;
        return reason = "word " + word + " has no number", false;
      }
      std::size_t end = j;
      while (end > i && is_blank(s[end - 1])) --end;
      GWord w;
      w.letter = letter;
      if (!exact_value(num, w.value)) {
        std::string number;  // sign, digits and point, without the blanks between
        for (std::size_t k = number_at; k < end; ++k)
          if (!is_blank(s[k])) number += s[k];
        w.value = parse_number(number);
      }
      w.pos = static_cast<std::uint32_t>(i);
      w.len = static_cast<std::uint32_t>(end - i);
      if (!std::isfinite(w.value) || std::fabs(w.value) > io::kMaxCoordinate)
        return reason = "number out of range: \"" + std::string(s.substr(i, end - i)) + "\"", false;
      if ((letter == 'X' || letter == 'Y') && num.after_point > b.decimals) b.decimals = num.after_point;
      sc.words.push_back(w);
      i = j;
    } else {
      return reason = std::string("unexpected character '") + c + "'", false;
    }
  }
  return true;
}

// A dynamic line's words for the modal state: a word with a plain number
// keeps it, the others are NaN (known only when the program runs).
bool dynamic_words(const GBlock& b, Scratch& sc, bool& oword, std::string& reason) {
  sc.words.clear();
  ExprPool pool;
  LineCode code;
  if (!parse_line(b.text, pool, code, reason)) return false;
  oword = code.oword != LineCode::Oword::none;
  for (const LineCode::Word& w : code.words) {
    const ExprNode& n = pool.nodes[static_cast<std::size_t>(w.expr)];
    GWord g;
    g.letter = w.letter;
    g.value = n.op == ExprNode::Op::number ? n.value : std::nan("");
    if ((w.letter == 'G' || w.letter == 'M') && std::isnan(g.value))
      return reason = std::string("a ") + w.letter + " code given by a parameter or an expression is not supported",
             false;
    sc.words.push_back(g);
  }
  return true;
}

// After a dynamic line: an axis it set from an expression is unknown, and
// after an O-word every position is.
void settle_dynamic(GBlock& b, Scratch& sc, State& st, bool oword) {
  st.flow = st.flow || oword;
  for (int k = 0; k < 3; ++k)
    if (oword || std::isnan(st.pos[k])) st.pos[k] = 0, st.known[k] = false;
  for (int k = 0; k < 3; ++k)
    if (std::isnan(b.end_pos[k])) b.end_pos[k] = 0;
  sc.words.clear();  // the flow computes them (job/gcode_flow.hpp)
  sc.unknown.clear();
}

std::string_view word_text(const GBlock& b, const GWord& w) { return b.text.substr(w.pos, w.len); }

// Applies one block to the modal state; false with a reason on a block kerf
// cannot follow.
bool apply_block(GBlock& b, Scratch& sc, State& st, std::string& reason) {
  double axis[3] = {0, 0, 0};
  bool has_axis[3] = {false, false, false};
  double ij[2] = {0, 0};
  bool has_ij = false, has_r = false, has_k = false;
  double r = 0;
  bool sets_origin = false, loses_position = false, other_words = false;
  int torch_change = 0;
  bool seen[26] = {};
  for (const GWord& w : sc.words) {
    const char L = w.letter;
    if (L == '$') {  // a tool head select: kept for the interpreter, passed through by weld
      sc.unknown.push_back(word_text(b, w));
      other_words = true;
      continue;
    }
    if (L != 'G' && L != 'M') {
      if (seen[L - 'A']) return reason = std::string("word ") + L + " appears twice", false;
      seen[L - 'A'] = true;
    }
    switch (L) {
      case 'G': {
        const int g = code10(w.value);
        if (g == 0 || g == 10 || g == 20 || g == 30) {
          st.motion = g == 0 ? Motion::rapid : g == 10 ? Motion::linear : g == 20 ? Motion::cw : Motion::ccw;
          b.motion_word = true;
        } else if (g == 170 || g == 180 || g == 190) {
          st.xy_plane = g == 170;
          other_words = true;
        } else if (g == 200 || g == 210) {
          const bool inches = g == 200;
          if (inches != st.inches)
            for (double& p : st.pos) p = inches ? p / kMmPerInch : p * kMmPerInch;
          st.inches = inches;
          other_words = true;
        } else if (g == 900 || g == 910) {
          st.relative = g == 910;
          other_words = true;
        } else if (g == 920) {
          sets_origin = true;
          other_words = true;
        } else if (g == 40 || g == 400 || g == 490 || g == 610 || g == 640 || g == 800 || g == 940) {
          other_words = true;  // dwell, no compensation, exact/blend, cancel, feed mode: no XY change
        } else {
          sc.unknown.push_back(word_text(b, w));
          loses_position = true;  // homing, work offsets, ...: kerf no longer knows where it is
          other_words = true;
        }
        break;
      }
      case 'M': {
        const int m = code10(w.value);
        if (m == 30 || m == 40) torch_change = 1;
        else if (m == 50) torch_change = -1;
        else if (m == 70 || m == 80 || m == 90 || m == 0 || m == 10 || m == 20 || m == 300) {
        } else sc.unknown.push_back(word_text(b, w));
        other_words = true;
        break;
      }
      case 'X': case 'Y': case 'Z': {
        const int k = L - 'X';
        axis[k] = w.value;
        has_axis[k] = true;
        break;
      }
      case 'I': ij[0] = w.value; has_ij = true; break;
      case 'J': ij[1] = w.value; has_ij = true; break;
      case 'K': has_k = true; break;
      case 'R': r = w.value; has_r = true; break;
      case 'F':
        b.has_f = true;
        b.new_feed = !(w.value == st.feed);  // NaN (no feed yet) compares unequal
        st.feed = w.value;
        break;
      case 'N': break;
      case 'S': case 'T': case 'P': other_words = true; break;
      default: sc.unknown.push_back(word_text(b, w)); other_words = true; break;
    }
  }
  if (torch_change != 0) st.torch = torch_change > 0;
  // A Z word that repeats the known Z (absolute) moves nothing: modal noise
  // that does not stop a run, like an F that repeats the feed in force.
  const bool z_same = has_axis[2] && st.known[2] && !st.relative && axis[2] == st.pos[2];
  for (int k = 0; k < 3; ++k) b.start[k] = st.pos[k];
  b.known_start = st.known[0] && st.known[1];
  const bool any_axis = has_axis[0] || has_axis[1] || has_axis[2];
  if (sets_origin) {  // G92: the current point gets the given coordinates
    for (int k = 0; k < 3; ++k)
      if (has_axis[k]) st.pos[k] = axis[k], st.known[k] = true;
  } else if (loses_position) {
    for (bool& k : st.known) k = false;
  } else if (any_axis || has_ij || has_r) {
    if (st.motion == Motion::none) return reason = "axis words with no motion mode (G0, G1, G2 or G3)", false;
    for (int k = 0; k < 3; ++k) {
      if (!has_axis[k]) continue;
      if (st.relative) st.pos[k] += axis[k];
      else st.pos[k] = axis[k], st.known[k] = true;
    }
    b.moves = true;
    const bool arc = st.motion == Motion::cw || st.motion == Motion::ccw;
    if (arc && st.xy_plane) {
      if (has_ij == has_r) return reason = has_r ? "an arc with both R and I/J" : "an arc without I J or R", false;
      if (has_k) return reason = "K on an arc in the XY plane (G17)", false;
      if (has_ij) {
        b.centre[0] = b.start[0] + ij[0];
        b.centre[1] = b.start[1] + ij[1];
      } else {
        const double dx = st.pos[0] - b.start[0], dy = st.pos[1] - b.start[1];
        const double d = std::hypot(dx, dy);
        if (d == 0) return reason = "an R arc needs an end point away from its start", false;
        double h2 = r * r - d * d / 4;
        if (h2 < 0) {
          if (d / 2 - std::fabs(r) > 1e-6 * (1 + std::fabs(r)))
            return reason = "R is smaller than half the distance to the end point", false;
          h2 = 0;
        }
        // Centre left of the chord for a CCW arc under 180 degrees (R > 0).
        double h = std::sqrt(h2) / d;
        if ((st.motion == Motion::cw) != (r < 0)) h = -h;
        b.centre[0] = b.start[0] + dx / 2 - h * dy;
        b.centre[1] = b.start[1] + dy / 2 + h * dx;
      }
    } else if (!arc && (has_ij || has_r)) {
      return reason = "I, J or R on a move that is not an arc", false;
    }
    (void)other_words;
    b.xy_line = st.motion == Motion::linear && st.xy_plane && (!has_axis[2] || z_same) && b.known_start &&
                sc.unknown.empty() && !other_words;
  }
  for (int k = 0; k < 3; ++k) b.end_pos[k] = st.pos[k];
  b.motion = st.motion;
  b.xy_plane = st.xy_plane;
  b.inches = st.inches;
  b.relative = st.relative;
  b.torch = st.torch;
  return true;
}

void collect_polylines(GcodeFile& f) {
  GPolyline cur;
  bool open = false;
  auto close = [&] {
    if (open && cur.points.size() >= 2) f.polylines.push_back(std::move(cur));
    cur = GPolyline{};
    open = false;
  };
  for (std::size_t i = 0; i < f.blocks.size(); ++i) {
    const GBlock& b = f.blocks[i];
    if (b.only_comment()) continue;  // comments and blank lines do not break a run
    if (!b.xy_line || (open && b.new_feed)) close();
    if (!b.xy_line) continue;
    if (!open) {
      open = true;
      cur.first_block = i;
      cur.points.push_back({b.start[0], b.start[1]});
      cur.point_block.push_back(i);
      cur.inches = b.inches;
      cur.relative = b.relative;
    }
    cur.points.push_back({b.end_pos[0], b.end_pos[1]});
    cur.point_block.push_back(i);
    cur.last_block = i;
  }
  close();
}

}  // namespace

namespace {

// Makes room for n more items in v, whose pages up to `mapped` (items) are
// mapped: it maps 256 KiB ahead at a time, so that filling v takes no page
// fault per 4 KiB and touches no memory the parse does not reach (a file
// refused at an early line).
template <class T>
void make_room(std::vector<T>& v, std::size_t& mapped, std::size_t n) {
  if (v.size() + n > v.capacity()) {
    v.reserve(2 * v.capacity() + n);
    io::prefer_huge_pages(v.data(), v.capacity() * sizeof(T));
    mapped = v.size();
  }
  if (v.size() + n > mapped) {
    mapped = std::min(v.capacity(), v.size() + std::max<std::size_t>(n, (256u << 10) / sizeof(T)));
    io::prefault(v.data() + v.size(), (mapped - v.size()) * sizeof(T));
  }
}

template <class T>
void append(std::vector<T>& to, std::size_t& mapped, const std::vector<T>& v) {
  make_room(to, mapped, v.size());
  to.insert(to.end(), v.begin(), v.end());
}

// Points each block's spans at its words and pieces in `src`, which no
// longer grows (each span's size was set as the block was parsed).
void bind_spans(GcodeFile& f, const GcodeFile::Source& src) {
  std::size_t word = 0, piece = 0;
  for (GBlock& b : f.blocks) {
    b.words = {src.words.data() + word, b.words.size()};
    word += b.words.size();
    b.comments = {src.pieces.data() + piece, b.comments.size()};
    piece += b.comments.size();
    b.unknown = {src.pieces.data() + piece, b.unknown.size()};
    piece += b.unknown.size();
  }
}

// Finds where each line ends. A file with an LF anywhere ends its lines at
// LF, and the CRs just before it belong to the line end ("\r\n", and
// "\r\r\n" from text mode applied twice); a file without one (CR only)
// ends them at CR. So a reader that splits at LF only and one that splits
// at CR or LF see the same lines (the second, some blank ones between).
class LineEnds {
 public:
  LineEnds(std::string_view text, bool lf) : text_(text), lf_(lf) {}
  // The end of the text of the line that starts at `at`; `next`: where its line end ends.
  std::size_t from(std::size_t at, std::size_t& next) const {
    const std::size_t j = find(lf_ ? '\n' : '\r', at);
    next = j < text_.size() ? j + 1 : j;
    std::size_t k = j;
    if (lf_ && j < text_.size())
      while (k > at && j - k < 2 && text_[k - 1] == '\r') --k;
    return k;
  }

 private:
  std::size_t find(char c, std::size_t at) const {
    const void* p = std::memchr(text_.data() + at, c, text_.size() - at);
    return p != nullptr ? static_cast<std::size_t>(static_cast<const char*>(p) - text_.data()) : text_.size();
  }

  std::string_view text_;
  bool lf_;
};

GcodeFile parse_source(std::string text_in, std::string display_name, GcodePart* part = nullptr) {
  GcodeFile f;
  f.file = std::move(display_name);
  auto src = std::make_shared<GcodeFile::Source>();
  src->text = std::move(text_in);
  const std::string_view text = src->text;
  State st = part != nullptr ? part->modal : State{};
  bool run_open = false;  // as collect_polylines sees the blocks, for part->run_block
  // One block per line and at most a word per letter, reserved at once:
  // growing them moved and faulted in megabytes.
  // (Counted apart, so that each loop is vectorised; a CRLF file counts
  // its lines twice, which only reserves more address space.)
  std::size_t lines = 1, letters = 0;
  for (const char c : text) lines += c == '\n' || c == '\r';
  for (const char c : text) letters += is_alpha(c);
  f.blocks.reserve(lines);
  src->words.reserve(std::min(letters, 8 * lines));
  io::prefer_huge_pages(f.blocks.data(), f.blocks.capacity() * sizeof(GBlock));
  io::prefer_huge_pages(src->words.data(), src->words.capacity() * sizeof(GWord));
  src->pieces.reserve(lines);  // a comment or an unknown word per line is common; more grows
  std::size_t blocks_mapped = 0, words_mapped = 0, pieces_mapped = 0;
  Scratch sc;
  std::size_t i = 0, line = part != nullptr ? part->first_line - 1 : 0;
  const bool has_lf = std::memchr(text.data(), '\n', text.size()) != nullptr;
  const bool has_cr = std::memchr(text.data(), '\r', text.size()) != nullptr;
  if (part != nullptr && !st.ends_known && (has_lf || has_cr)) st.ends_known = true, st.lf_ends = has_lf;
  const bool lf = part != nullptr && st.ends_known ? st.lf_ends : has_lf || !has_cr;
  const LineEnds ends(text, lf);
  auto refuse = [&](std::string why) {
    fail(f, line, std::move(why));
    bind_spans(f, *src);
    f.source = std::move(src);
  };
  while (i < text.size()) {
    ++line;
    std::size_t next = 0;
    const std::size_t j = ends.from(i, next);
    if (j - i > io::kMaxLineBytes) {
      refuse("line longer than 65536 bytes (not a G-code file?)");
      return f;
    }
    GBlock b;
    b.line = line;
    b.text = text.substr(i, j - i);
    b.end = text.substr(j, next - j);
    i = next;
    std::string reason;
    if (lf && has_cr && b.text.find('\r') != std::string::npos)
      reason = "a CR inside a line (this file's lines end with LF: readers that also end lines at CR "
               "would see another program)";
    else if (!lf && has_lf && b.text.find('\n') != std::string::npos)
      reason = "an LF in a file whose lines end with CR";
    sc.words.clear();
    sc.comments.clear();
    sc.unknown.clear();
    if (reason.empty() && b.text.find('\0') != std::string::npos) reason = "a NUL byte (not a text file?)";
    bool oword = false;
    const State before = st;
    if (!reason.empty() || !split_words(b, sc, reason) ||
        (b.dynamic && !dynamic_words(b, sc, oword, reason)) || !apply_block(b, sc, st, reason)) {
      refuse(std::move(reason));
      return f;
    }
    if (b.dynamic) settle_dynamic(b, sc, st, oword);
    if (st.flow || b.dynamic) b.xy_line = false;
    if (b.decimals > f.decimals) f.decimals = b.decimals;
    // The spans get their place in bind_spans; their sizes are kept here.
    append(src->words, words_mapped, sc.words);
    if (!sc.comments.empty()) append(src->pieces, pieces_mapped, sc.comments);  // most lines have none
    if (!sc.unknown.empty()) append(src->pieces, pieces_mapped, sc.unknown);
    b.words = {src->words.data(), sc.words.size()};
    b.comments = {src->pieces.data(), sc.comments.size()};
    b.unknown = {src->pieces.data(), sc.unknown.size()};
    if (part != nullptr && !b.only_comment()) {
      if (!b.xy_line || b.new_feed) run_open = false, part->run_block = static_cast<std::size_t>(-1);
      if (b.xy_line && !run_open) run_open = true, part->run_block = f.blocks.size(), part->at_run = before;
    }
    make_room(f.blocks, blocks_mapped, 1);
    f.blocks.push_back(b);
  }
  bind_spans(f, *src);
  f.source = std::move(src);
  if (part != nullptr) part->modal = st;
  collect_polylines(f);
  f.ok = true;
  return f;
}

}  // namespace

GcodeFile parse_gcode(std::string_view text, std::string display_name) {
  return parse_source(std::string(text), std::move(display_name));
}

GcodeFile parse_gcode_part(std::string text, std::string display_name, GcodePart& part) {
  part.run_block = static_cast<std::size_t>(-1);
  return parse_source(std::move(text), std::move(display_name), &part);
}

GcodeFile read_gcode(const std::string& path) {
  const bool use_stdin = path == "-";
  std::FILE* in = use_stdin ? stdin : std::fopen(path.c_str(), "rb");
  GcodeFile f;
  f.file = use_stdin ? "<stdin>" : path;
  if (in == nullptr) {
    f.reason = std::strerror(errno);
    return f;
  }
  if (!use_stdin) {  // a directory opens, and its size probe asks for 2^63 bytes
    f.reason = io::input_problem(path);
    if (!f.reason.empty()) {
      std::fclose(in);
      return f;
    }
  }
  std::string text;
  if (!use_stdin && std::fseek(in, 0, SEEK_END) == 0) {  // one allocation for the whole file
    const long size = std::ftell(in);
    if (size > 0) text.reserve(static_cast<std::size_t>(size) + 1);  // + 1: the read that finds the end
    std::rewind(in);
  }
  // Read in chunks straight into the text, each chunk's pages mapped at once.
  // Reading stops after a chunk that ends inside a line longer than
  // kMaxLineBytes (parse_gcode then reports it, or an earlier error), so a
  // runaway line is not read whole.
  constexpr std::size_t kChunk = 1u << 20;
  std::size_t line_bytes = 0;
  bool too_long = false;
  while (!too_long) {
    const std::size_t have = text.size();
    if (text.capacity() == have) text.reserve(2 * have + kChunk);
    const std::size_t chunk = std::min(kChunk, text.capacity() - have);
    io::prefault(text.data() + have, chunk);
    text.resize(have + chunk);
    const std::size_t n = std::fread(text.data() + have, 1, chunk, in);
    text.resize(have + n);
    // The chunk's last line end, looked for from its end (a byte or twenty
    // back in a G-code file, the whole chunk once in a file without any).
    std::size_t k = have + n;
    while (k > have && text[k - 1] != '\n' && text[k - 1] != '\r') --k;
    line_bytes = k > have ? have + n - k : line_bytes + n;
    too_long = line_bytes > io::kMaxLineBytes;
    if (n < chunk) break;
  }
  const bool bad = std::ferror(in) != 0;
  if (!use_stdin) std::fclose(in);
  if (bad) {
    f.reason = "read error";
    return f;
  }
  return parse_source(std::move(text), f.file);
}

std::string describe_error(const GcodeFile& f) {
  return f.line == 0 ? f.file + ": " + f.reason : f.file + ":" + std::to_string(f.line) + ": " + f.reason;
}

}  // namespace kerf::job
