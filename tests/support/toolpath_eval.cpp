#include "toolpath_eval.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>

namespace kerf_test {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Upper case, blanks and comments gone.
std::string squeeze(const std::string& raw) {
  std::string s;
  int depth = 0;
  for (char c : raw) {
    if (depth > 0) { depth -= c == ')'; continue; }
    if (c == '(') { ++depth; continue; }
    if (c == ';') break;
    if (c == ' ' || c == '\t' || c == '\r') continue;
    s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return s;
}

struct Frame {
  std::size_t back = 0;  // the line index to return to
  double args[31] = {};
  std::map<std::string, double> locals;
};

class Machine {
 public:
  explicit Machine(const std::string& text) {
    std::istringstream in(text);
    std::string raw;
    while (std::getline(in, raw)) raw_.push_back(raw), lines_.push_back(squeeze(raw));
    frames_.emplace_back();
  }

  bool run(std::vector<RunLine>& out, std::string& why, std::size_t max_lines) {
    std::size_t steps = 0;
    for (pc_ = 0; pc_ < lines_.size();) {
      if (++steps > max_lines) return fail("more lines run than the cap (a loop that never ends?)", why);
      const std::string& s = lines_[pc_];
      err_.clear();
      if (!s.empty() && s[0] == 'O') {
        if (!oword(s)) return fail(err_, why);
        continue;
      }
      if (s.find_first_of("#[") == std::string::npos) {
        out.push_back({pc_ + 1, raw_[pc_]});
        ++pc_;
        continue;
      }
      std::string plain;
      if (!plain_line(s, plain)) return fail(err_, why);
      out.push_back({pc_ + 1, plain});
      ++pc_;
    }
    return true;
  }

 private:
  bool fail(const std::string& e, std::string& why) {
    why = std::to_string(pc_ + 1) + ": " + (e.empty() ? "malformed" : e);
    return false;
  }
  bool bad(const char* e) { if (err_.empty()) err_ = e; return false; }

  // A line's words with their values, its assignments after every read.
  bool plain_line(const std::string& s, std::string& plain) {
    std::vector<std::pair<std::string, double>> named;
    std::vector<std::pair<int, double>> numbered;
    i_ = 0;
    while (i_ < s.size()) {
      if (s[i_] == '#') {
        ++i_;
        std::string name;
        int n = 0;
        double v = 0;
        if (!target(s, name, n) || i_ >= s.size() || s[i_++] != '=' || !value(s, v)) return bad("bad assignment");
        if (name.empty()) numbered.push_back({n, v});
        else named.push_back({name, v});
        continue;
      }
      const char letter = s[i_++];
      double v = 0;
      if (!std::isalpha(static_cast<unsigned char>(letter)) && letter != '$') return bad("unexpected character");
      if (!value(s, v)) return false;
      char buf[64];
      std::snprintf(buf, sizeof buf, "%c%.10f", letter, v);
      plain += buf;
    }
    for (auto& [n, v] : numbered) param(n) = v;
    for (auto& [name, v] : named) scope(name)[name] = v;
    return true;
  }

  // After '#': a name (#<..>) or a number (#n, #[..], ##n).
  bool target(const std::string& s, std::string& name, int& n) {
    if (i_ < s.size() && s[i_] == '<') {
      const std::size_t close = s.find('>', i_);
      if (close == std::string::npos) return bad("unclosed #<");
      name = s.substr(i_ + 1, close - i_ - 1);
      for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      i_ = close + 1;
      return true;
    }
    double v = 0;
    if (!value(s, v)) return false;
    n = static_cast<int>(std::lround(v));
    if (n < 1 || n > 5602) return bad("parameter number out of range");
    return true;
  }
  double& param(int n) { return n <= 30 ? frames_.back().args[n] : numbered_[n]; }
  std::map<std::string, double>& scope(const std::string& name) {
    return name[0] == '_' ? globals_ : frames_.back().locals;
  }

  bool value(const std::string& s, double& v) {
    if (i_ >= s.size()) return bad("missing value");
    const char c = s[i_];
    if (c == '[') {
      ++i_;
      if (!binary(s, 0, v)) return false;
      if (i_ >= s.size() || s[i_] != ']') return bad("missing ]");
      ++i_;
      return true;
    }
    if (c == '#') {
      ++i_;
      std::string name;
      int n = 0;
      if (!target(s, name, n)) return false;
      if (name.empty()) return v = param(n), true;
      if (name.rfind("_hal[", 0) == 0) return v = 0, true;
      auto& m = scope(name);
      if (m.count(name) == 0) return bad("unset named parameter");
      return v = m[name], true;
    }
    if ((c == '-' || c == '+') && i_ + 1 < s.size() && !std::isdigit(static_cast<unsigned char>(s[i_ + 1])) &&
        s[i_ + 1] != '.') {
      ++i_;
      if (!value(s, v)) return false;
      if (c == '-') v = -v;
      return true;
    }
    if (std::isalpha(static_cast<unsigned char>(c))) return function(s, v);
    const std::size_t from = i_;
    if (c == '-' || c == '+') ++i_;
    while (i_ < s.size() && (std::isdigit(static_cast<unsigned char>(s[i_])) || s[i_] == '.')) ++i_;
    if (i_ == from) return bad("missing number");
    v = std::strtod(s.substr(from, i_ - from).c_str(), nullptr);
    return true;
  }

  bool function(const std::string& s, double& v) {
    std::size_t end = i_;
    while (end < s.size() && std::isalpha(static_cast<unsigned char>(s[end]))) ++end;
    const std::string f = s.substr(i_, end - i_);
    i_ = end;
    if (f == "EXISTS") {
      if (s.compare(i_, 2, "[#") != 0) return bad("EXISTS[#<name>]");
      i_ += 2;
      std::string name;
      int n = 0;
      if (!target(s, name, n) || name.empty() || i_ >= s.size() || s[i_++] != ']') return bad("EXISTS[#<name>]");
      return v = scope(name).count(name) != 0, true;
    }
    double a = 0, b = 0;
    if (i_ >= s.size() || s[i_] != '[' || !value(s, a)) return bad("function without [argument]");
    if (f == "ATAN") {
      if (i_ >= s.size() || s[i_++] != '/' || !value(s, b)) return bad("ATAN[y]/[x]");
      return v = std::atan2(a, b) / kDeg, true;
    }
    if (f == "ABS") v = std::fabs(a);
    else if (f == "ACOS" && std::fabs(a) <= 1) v = std::acos(a) / kDeg;
    else if (f == "ASIN" && std::fabs(a) <= 1) v = std::asin(a) / kDeg;
    else if (f == "COS") v = std::cos(a * kDeg);
    else if (f == "SIN") v = std::sin(a * kDeg);
    else if (f == "TAN") v = std::tan(a * kDeg);
    else if (f == "EXP") v = std::exp(a);
    else if (f == "FIX") v = std::floor(a);
    else if (f == "FUP") v = std::ceil(a);
    else if (f == "LN" && a > 0) v = std::log(a);
    else if (f == "ROUND") v = a < 0 ? -std::floor(-a + 0.5) : std::floor(a + 0.5);
    else if (f == "SQRT" && a >= 0) v = std::sqrt(a);
    else return bad("unknown function or argument out of range");
    return true;
  }

  // Precedence: ** > * / MOD > + - > comparisons > AND OR XOR.
  bool binary(const std::string& s, int level, double& v) {
    static const std::vector<std::vector<std::string>> kOps = {
        {"AND", "OR", "XOR"}, {"EQ", "NE", "GT", "GE", "LT", "LE"}, {"+", "-"}, {"*", "/", "MOD"}, {"**"}};
    if (level == 5) return value(s, v);
    if (!binary(s, level + 1, v)) return false;
    for (;;) {
      std::string op;
      for (const std::string& o : kOps[static_cast<std::size_t>(level)])
        if (s.compare(i_, o.size(), o) == 0 && !(o == "*" && s.compare(i_, 2, "**") == 0)) op = o;
      if (op.empty()) return true;
      i_ += op.size();
      double r = 0;
      if (!binary(s, level + 1, r)) return false;
      const bool eq = std::fabs(v - r) < 1e-6;
      if (op == "**") v = std::pow(v, r);
      else if (op == "*") v *= r;
      else if (op == "/") { if (r == 0) return bad("division by zero"); v /= r; }
      else if (op == "MOD") { if (r == 0) return bad("MOD by zero"); v = std::fmod(v, r); if (v < 0) v += std::fabs(r); }
      else if (op == "+") v += r;
      else if (op == "-") v -= r;
      else if (op == "EQ") v = eq;
      else if (op == "NE") v = !eq;
      else if (op == "GT") v = v > r;
      else if (op == "GE") v = eq || v >= r;
      else if (op == "LT") v = v < r;
      else if (op == "LE") v = eq || v <= r;
      else if (op == "AND") v = v != 0 && r != 0;
      else if (op == "OR") v = v != 0 || r != 0;
      else v = (v != 0) != (r != 0);
    }
  }

  // "O<name>KEYWORD[args]": the name (with its < >) and keyword.
  static bool split_o(const std::string& s, std::string& name, std::string& key, std::size_t& args) {
    std::size_t i = 1;
    if (i < s.size() && s[i] == '<') i = s.find('>', i) == std::string::npos ? s.size() : s.find('>', i) + 1;
    else while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    name = s.substr(1, i - 1);
    while (name.size() > 1 && name[0] == '0') name.erase(0, 1);
    std::size_t k = i;
    while (k < s.size() && std::isalpha(static_cast<unsigned char>(s[k]))) ++k;
    key = s.substr(i, k - i);
    args = k;
    return !name.empty() && !key.empty();
  }
  // The next line (from `from`, one way) with this name and one of `keys`.
  std::size_t find(std::size_t from, const std::string& name, std::initializer_list<const char*> keys, int step) {
    for (long long k = static_cast<long long>(from); k >= 0 && k < static_cast<long long>(lines_.size()); k += step) {
      std::string n, key;
      std::size_t a = 0;
      const std::string& s = lines_[static_cast<std::size_t>(k)];
      if (s.empty() || s[0] != 'O' || !split_o(s, n, key, a) || n != name) continue;
      for (const char* want : keys)
        if (key == want) return static_cast<std::size_t>(k);
    }
    return lines_.size();
  }
  bool cond(const std::string& s, std::size_t at, double& v) {
    i_ = at;
    return value(s, v);
  }

  bool oword(const std::string& s) {
    std::string name, key;
    std::size_t a = 0;
    if (!split_o(s, name, key, a)) return bad("malformed O-word");
    const std::size_t none = lines_.size();
    double v = 0;
    auto go = [&](std::size_t to) { if (to >= none) return bad("O-word without its end"); pc_ = to; return true; };
    if (key == "SUB") return go(find(pc_ + 1, name, {"ENDSUB"}, 1)) && (++pc_, true);
    if (key == "ENDSUB" || key == "RETURN") {
      if (frames_.size() == 1) return ++pc_, true;
      pc_ = frames_.back().back;
      frames_.pop_back();
      return true;
    }
    if (key == "CALL") {
      const std::size_t sub = find(0, name, {"SUB"}, 1);
      if (sub >= none) return bad("no such subroutine in the file");
      if (frames_.size() > 50) return bad("calls nested too deep");
      Frame f;
      f.back = pc_ + 1;
      for (int n = 1; i_ = a, a < s.size(); ++n) {
        if (n > 30 || !value(s, v)) return bad("bad call argument");
        f.args[n] = v;
        a = i_;
      }
      frames_.push_back(f);
      pc_ = sub + 1;
      return true;
    }
    if (key == "IF") {  // the first branch whose condition holds, else the else, else past the endif
      for (std::size_t j = pc_; j < none; j = find(j + 1, name, {"ELSEIF", "ELSE", "ENDIF"}, 1)) {
        const std::string k = key_of(j);
        if (k == "ELSE" || k == "ENDIF") return pc_ = j + 1, true;
        std::string n2, k2;
        std::size_t a2 = 0;
        split_o(lines_[j], n2, k2, a2);
        if (!cond(lines_[j], a2, v)) return false;
        if (v != 0) return pc_ = j + 1, true;
      }
      return bad("if without endif");
    }
    if (key == "ELSEIF" || key == "ELSE") return go(find(pc_, name, {"ENDIF"}, 1)) && (++pc_, true);  // a branch ran
    if (key == "ENDIF" || key == "DO") return ++pc_, true;
    if (key == "WHILE") {
      if (!cond(s, a, v)) return false;
      const std::size_t end = find(pc_ + 1, name, {"ENDWHILE", "DO", "WHILE"}, 1);
      if (end < none && key_of(end) == "ENDWHILE")  // a loop head
        return v != 0 ? (++pc_, true) : (pc_ = end + 1, true);
      if (v != 0) return go(find(pc_, name, {"DO"}, -1)) && (++pc_, true);  // a do's tail
      return ++pc_, true;
    }
    if (key == "ENDWHILE") return go(find(pc_, name, {"WHILE"}, -1));
    if (key == "REPEAT") {
      if (!cond(s, a, v)) return false;
      if (v < 1) return go(find(pc_ + 1, name, {"ENDREPEAT"}, 1)) && (++pc_, true);
      counts_.push_back({pc_, static_cast<long long>(v)});
      return ++pc_, true;
    }
    if (key == "ENDREPEAT") {
      const std::size_t head = find(pc_, name, {"REPEAT"}, -1);
      if (counts_.empty() || counts_.back().first != head) return bad("endrepeat without its repeat");
      if (--counts_.back().second > 0) return pc_ = head + 1, true;
      counts_.pop_back();
      return ++pc_, true;
    }
    if (key == "BREAK" || key == "CONTINUE") {
      const std::size_t end = find(pc_, name, {"ENDWHILE", "ENDREPEAT", "WHILE"}, 1);
      if (end >= none) return bad("break outside a loop");
      const bool repeat = key_of(end) == "ENDREPEAT";
      if (key == "BREAK") {
        if (repeat) counts_.pop_back();
        return pc_ = end + 1, true;
      }
      if (key_of(end) == "ENDWHILE") return go(find(pc_, name, {"WHILE"}, -1));
      return pc_ = end, true;
    }
    return bad("unknown O-word");
  }
  std::string key_of(std::size_t k) const {
    std::string n, key;
    std::size_t a = 0;
    split_o(lines_[k], n, key, a);
    return key;
  }

  std::vector<std::string> raw_, lines_;
  std::vector<Frame> frames_;
  std::map<int, double> numbered_;
  std::map<std::string, double> globals_;
  std::vector<std::pair<std::size_t, long long>> counts_;
  std::size_t pc_ = 0, i_ = 0;
  std::string err_;
};

}  // namespace

bool run_program(const std::string& text, std::vector<RunLine>& out, std::string& why, std::size_t max_lines) {
  out.clear();
  return Machine(text).run(out, why, max_lines);
}

}  // namespace kerf_test
