#include "job/gcode_expr.hpp"

#include <cmath>
#include <cstdlib>

#include "job/gcode_params.hpp"

namespace kerf::job {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEqualTolerance = 1e-6;  // LinuxCNC's TOLERANCE_EQUAL for EQ NE LE GE

// The unary functions, by name (ATAN and EXISTS have their own forms).
constexpr const char* kFunctions[] = {"abs", "acos", "asin", "cos", "exp", "fix", "fup", "ln", "round", "sin",
                                      "sqrt", "tan"};

struct BinaryOp {
  const char* text;
  ExprNode::Op op;
  int precedence;  // higher binds tighter
};
// Longer spellings first where one is a prefix of another (** before *).
constexpr BinaryOp kBinary[] = {
    {"**", ExprNode::Op::pow, 4}, {"*", ExprNode::Op::mul, 3},  {"/", ExprNode::Op::div, 3},
    {"mod", ExprNode::Op::mod, 3}, {"+", ExprNode::Op::add, 2}, {"-", ExprNode::Op::sub, 2},
    {"eq", ExprNode::Op::eq, 1},  {"ne", ExprNode::Op::ne, 1},  {"gt", ExprNode::Op::gt, 1},
    {"ge", ExprNode::Op::ge, 1},  {"lt", ExprNode::Op::lt, 1},  {"le", ExprNode::Op::le, 1},
    {"and", ExprNode::Op::and_, 0}, {"or", ExprNode::Op::or_, 0}, {"xor", ExprNode::Op::xor_, 0},
};

struct OwordName {
  const char* text;
  LineCode::Oword kind;
};
// endsub before sub is not needed (prefix match is by the whole rest of the keyword).
constexpr OwordName kOwords[] = {
    {"endsub", LineCode::Oword::endsub},     {"endwhile", LineCode::Oword::endwhile},
    {"endrepeat", LineCode::Oword::endrepeat}, {"endif", LineCode::Oword::endif},
    {"elseif", LineCode::Oword::elseif},     {"else", LineCode::Oword::else_},
    {"sub", LineCode::Oword::sub},           {"call", LineCode::Oword::call},
    {"do", LineCode::Oword::do_},            {"while", LineCode::Oword::while_},
    {"if", LineCode::Oword::if_},            {"break", LineCode::Oword::break_},
    {"continue", LineCode::Oword::continue_}, {"repeat", LineCode::Oword::repeat},
    {"return", LineCode::Oword::return_},
};

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_lower(char c) { return c >= 'a' && c <= 'z'; }

class Parser {
 public:
  Parser(std::string s, ExprPool& pool) : s_(std::move(s)), pool_(pool) {}

  bool line(LineCode& out, std::string& reason) {
    if (!s_.empty() && s_[0] == 'n') {  // a line number: kept as an N word
      ++i_;
      int n = -1;
      if (!number(n)) return fail(reason);
      out.words.push_back({'N', n});
    }
    if (at('o')) return oword(out, reason);
    while (i_ < s_.size()) {
      if (too_deep_) return err("an expression nested deeper than 200"), fail(reason);
      const char c = s_[i_];
      if (c == '#') {
        LineCode::Assign a;
        if (!param(a.target) || !expect('=') || !value(a.expr)) return fail(reason);
        out.assigns.push_back(a);
      } else if (is_lower(c) || c == '$') {
        if (c == 'o') return err("an O-word must begin its line"), fail(reason);
        ++i_;
        LineCode::Word w;
        w.letter = c == '$' ? '$' : static_cast<char>(c - 'a' + 'A');
        if (!value(w.expr)) return fail(reason);
        out.words.push_back(w);
      } else {
        return err(std::string("unexpected character '") + c + "'"), fail(reason);
      }
    }
    return true;
  }

 private:
  bool fail(std::string& reason) {
    reason = why_.empty() ? "malformed line" : why_;
    return false;
  }
  bool err(std::string why) {
    if (why_.empty()) why_ = std::move(why);
    return false;
  }
  bool at(char c) const { return i_ < s_.size() && s_[i_] == c; }
  bool starts(const char* t) const { return s_.compare(i_, std::char_traits<char>::length(t), t) == 0; }
  bool expect(char c) {
    if (!at(c)) return err(std::string("expected '") + c + "'" + (i_ < s_.size() ? "" : " at the end of the line"));
    ++i_;
    return true;
  }
  int add(ExprNode n) {
    for (const int c : {n.a, n.b})
      if (c >= 0 && pool_.nodes[static_cast<std::size_t>(c)].depth >= n.depth) n.depth = pool_.nodes[static_cast<std::size_t>(c)].depth + 1;
    if (n.depth > kMaxDepth) too_deep_ = true;
    pool_.nodes.push_back(std::move(n));
    return static_cast<int>(pool_.nodes.size() - 1);
  }

  bool oword(LineCode& out, std::string& reason) {
    ++i_;
    if (at('<')) {
      const std::size_t close = s_.find('>', i_);
      if (close == std::string::npos) return err("o<name without its closing >"), fail(reason);
      out.oname = s_.substr(i_, close + 1 - i_);
      i_ = close + 1;
    } else {
      const std::size_t from = i_;
      while (i_ < s_.size() && is_digit(s_[i_])) ++i_;
      if (i_ == from) return err("an O-word needs a number or a <name>"), fail(reason);
      out.oname = s_.substr(from, i_ - from);
      while (out.oname.size() > 1 && out.oname[0] == '0') out.oname.erase(0, 1);  // o010 is o10
    }
    for (const OwordName& k : kOwords)
      if (starts(k.text)) {
        out.oword = k.kind;
        i_ += std::char_traits<char>::length(k.text);
        break;
      }
    if (out.oword == LineCode::Oword::none)
      return err("o" + out.oname + " without a keyword (sub, call, if, while, repeat, ...)"), fail(reason);
    while (at('[')) {
      int e = -1;
      if (!value(e)) return fail(reason);
      out.args.push_back(e);
    }
    if (i_ < s_.size()) return err("unexpected text after o" + out.oname + " " + oword_name(out.oword)), fail(reason);
    return true;
  }

  bool number(int& out) {
    const std::size_t from = i_;
    if (at('+') || at('-')) ++i_;
    bool digits = false, point = false;
    while (i_ < s_.size() && (is_digit(s_[i_]) || (s_[i_] == '.' && !point))) {
      point = point || s_[i_] == '.';
      digits = digits || is_digit(s_[i_]);
      ++i_;
    }
    if (!digits) return err(i_ < s_.size() ? "a value is missing" : "a value is missing at the end of the line");
    ExprNode n;
    n.value = std::strtod(s_.substr(from, i_ - from).c_str(), nullptr);
    out = add(n);
    return true;
  }

  // #n, #[expr], ##n, #<name>.
  bool param(int& out) {
    ++i_;  // '#'
    ExprNode n;
    if (at('<')) {
      const std::size_t close = s_.find('>', i_);
      if (close == std::string::npos) return err("#<name without its closing >");
      n.op = ExprNode::Op::named;
      n.name = s_.substr(i_ + 1, close - i_ - 1);
      if (n.name.empty()) return err("#<> has no name");
      i_ = close + 1;
    } else {
      n.op = ExprNode::Op::param;
      if (!value(n.a)) return false;
    }
    out = add(n);
    return true;
  }

  bool value(int& out) {
    if (i_ >= s_.size()) return err("a value is missing at the end of the line");
    const char c = s_[i_];
    if (c == '[') return bracket(out);
    if (c == '#') {
      if (++nesting_ > kMaxDepth) return err("parameters nested deeper than 200");
      const bool ok = param(out);
      --nesting_;
      return ok;
    }
    const bool sign = c == '+' || c == '-';
    if (sign && i_ + 1 < s_.size() && !is_digit(s_[i_ + 1]) && s_[i_ + 1] != '.') {
      ++i_;
      int v = -1;
      if (++nesting_ > kMaxDepth) return err("signs nested deeper than 200");
      if (!value(v)) return false;
      --nesting_;
      if (c == '+') return out = v, true;
      ExprNode n;
      n.op = ExprNode::Op::unary_minus;
      n.a = v;
      out = add(n);
      return true;
    }
    if (is_lower(c)) return function(out);
    return number(out);
  }

  bool bracket(int& out) {
    ++i_;  // '['
    if (++nesting_ > kMaxDepth || too_deep_) return err("an expression nested deeper than 200");
    if (!binary(0, out)) return false;
    --nesting_;
    if (too_deep_) return err("an expression nested deeper than 200");
    return expect(']');
  }

  // Precedence climbing, left associative.
  bool binary(int min_prec, int& out) {
    if (!value(out)) return false;
    for (;;) {
      const BinaryOp* op = nullptr;
      for (const BinaryOp& b : kBinary)
        if (starts(b.text)) {
          op = &b;
          break;
        }
      if (op == nullptr || op->precedence < min_prec) return true;
      i_ += std::char_traits<char>::length(op->text);
      int rhs = -1;
      if (!binary(op->precedence + 1, rhs)) return false;
      ExprNode n;
      n.op = op->op;
      n.a = out;
      n.b = rhs;
      out = add(n);
    }
  }

  bool function(int& out) {
    ExprNode n;
    if (starts("atan")) {
      i_ += 4;
      n.op = ExprNode::Op::atan;
      if (!at('[') || !bracket(n.a) || !expect('/') || !at('[') || !bracket(n.b))
        return err("ATAN takes the form ATAN[y]/[x]");
      out = add(n);
      return true;
    }
    if (starts("exists")) {
      i_ += 6;
      if (!expect('[') || !at('#') || !param(n.a) || !expect(']')) return err("EXISTS takes the form EXISTS[#<name>]");
      if (pool_.nodes[static_cast<std::size_t>(n.a)].op != ExprNode::Op::named)
        return err("EXISTS takes a named parameter");
      n.op = ExprNode::Op::exists;
      n.name = pool_.nodes[static_cast<std::size_t>(n.a)].name;
      out = add(n);
      return true;
    }
    for (std::size_t k = 0; k < std::size(kFunctions); ++k)
      if (starts(kFunctions[k]) && s_.compare(i_ + std::char_traits<char>::length(kFunctions[k]), 1, "[") == 0) {
        i_ += std::char_traits<char>::length(kFunctions[k]);
        n.op = ExprNode::Op::func;
        n.func = static_cast<std::uint8_t>(k);
        if (!bracket(n.a)) return false;
        out = add(n);
        return true;
      }
    std::size_t end = i_;
    while (end < s_.size() && is_lower(s_[end])) ++end;
    return err("unknown function or word \"" + s_.substr(i_, end - i_) + "\" where a value is expected");
  }

  static constexpr int kMaxDepth = 200;
  std::string s_;
  std::size_t i_ = 0;
  ExprPool& pool_;
  bool too_deep_ = false;
  int nesting_ = 0;
  std::string why_;
};

// The line without blanks and comments, case folded (as LinuxCNC reads it).
bool normalize(std::string_view text, std::string& s, std::string& reason) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ';') break;
    if (c == '(') {
      const std::size_t close = text.find(')', i);
      if (close == std::string_view::npos) return reason = "unclosed ( comment", false;
      i = close;
    } else if (c != ' ' && c != '\t') {
      s += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    }
  }
  return true;
}

bool domain(bool ok, const char* what, std::string& reason) {
  if (!ok) reason = what;
  return ok;
}

bool apply_func(std::size_t f, double& v, std::string& reason) {
  const double deg = kPi / 180.0;
  switch (f) {
    case 0: v = std::fabs(v); return true;
    case 1: if (!domain(v >= -1 && v <= 1, "ACOS of a value outside -1..1", reason)) return false;
            v = std::acos(v) / deg; return true;
    case 2: if (!domain(v >= -1 && v <= 1, "ASIN of a value outside -1..1", reason)) return false;
            v = std::asin(v) / deg; return true;
    case 3: v = std::cos(v * deg); return true;
    case 4: v = std::exp(v); return true;
    case 5: v = std::floor(v); return true;
    case 6: v = std::ceil(v); return true;
    case 7: if (!domain(v > 0, "LN of a value <= 0", reason)) return false;
            v = std::log(v); return true;
    case 8: v = v < 0 ? std::ceil(v - 0.5) : std::floor(v + 0.5); return true;  // halves away from 0
    case 9: v = std::sin(v * deg); return true;
    case 10: if (!domain(v >= 0, "SQRT of a negative value", reason)) return false;
             v = std::sqrt(v); return true;
    default: v = std::tan(v * deg); return true;
  }
}

bool binary_op(ExprNode::Op op, double l, double r, double& v, std::string& reason) {
  using Op = ExprNode::Op;
  switch (op) {
    case Op::pow:
      if (!domain(!(l < 0 && std::floor(r) != r), "a negative number raised to a non-integer power", reason))
        return false;
      v = std::pow(l, r); return true;
    case Op::mul: v = l * r; return true;
    case Op::div: if (!domain(r != 0, "division by zero", reason)) return false;
                  v = l / r; return true;
    case Op::mod: if (!domain(r != 0, "MOD by zero", reason)) return false;
                  v = std::fmod(l, r);
                  if (v < 0) v += std::fabs(r);  // LinuxCNC: always >= 0
                  return true;
    case Op::add: v = l + r; return true;
    case Op::sub: v = l - r; return true;
    case Op::eq: v = std::fabs(l - r) < kEqualTolerance; return true;
    case Op::ne: v = std::fabs(l - r) >= kEqualTolerance; return true;
    case Op::gt: v = l > r; return true;
    case Op::ge: v = std::fabs(l - r) < kEqualTolerance || l >= r; return true;
    case Op::lt: v = l < r; return true;
    case Op::le: v = std::fabs(l - r) < kEqualTolerance || l <= r; return true;
    case Op::and_: v = l != 0 && r != 0; return true;
    case Op::or_: v = l != 0 || r != 0; return true;
    case Op::xor_: v = (l != 0) != (r != 0); return true;
    default: return false;
  }
}

}  // namespace

const char* oword_name(LineCode::Oword o) {
  for (const OwordName& k : kOwords)
    if (k.kind == o) return k.text;
  return "?";
}

bool parse_line(std::string_view text, ExprPool& pool, LineCode& out, std::string& reason) {
  std::string s;
  if (!normalize(text, s, reason)) return false;
  if (!s.empty() && s[0] == '/') return reason = "block delete (/) is not supported", false;
  return Parser(std::move(s), pool).line(out, reason);
}

bool eval_expr(const ExprPool& pool, int n, GcodeParams& params, double& out, std::string& reason) {
  using Op = ExprNode::Op;
  const ExprNode& e = pool.nodes[static_cast<std::size_t>(n)];
  double a = 0, b = 0;
  switch (e.op) {
    case Op::number: out = e.value; return true;
    case Op::named: return params.read(e.name, out, reason);
    case Op::exists: out = params.exists(e.name); return true;
    case Op::param: {
      if (!eval_expr(pool, e.a, params, a, reason)) return false;
      const double r = std::round(a);
      if (std::fabs(a - r) > 1e-4 || std::fabs(r) > 1e6)
        return reason = "a parameter number must be an integer", false;
      return params.read(static_cast<int>(r), out, reason);
    }
    case Op::unary_minus:
      if (!eval_expr(pool, e.a, params, a, reason)) return false;
      out = -a;
      return true;
    case Op::func:
      if (!eval_expr(pool, e.a, params, a, reason) || !apply_func(e.func, a, reason)) return false;
      out = a;
      break;
    case Op::atan:
      if (!eval_expr(pool, e.a, params, a, reason) || !eval_expr(pool, e.b, params, b, reason)) return false;
      out = std::atan2(a, b) * 180.0 / kPi;
      break;
    default:
      if (!eval_expr(pool, e.a, params, a, reason) || !eval_expr(pool, e.b, params, b, reason) ||
          !binary_op(e.op, a, b, out, reason))
        return false;
  }
  if (!std::isfinite(out)) return reason = "the result is not a finite number", false;
  return true;
}

}  // namespace kerf::job
