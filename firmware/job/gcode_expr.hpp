// The parameters, expressions and O-word lines of RS274/NGC, with LinuxCNC's
// meaning (its G-code reference: overview.adoc "Parameters", "Expressions",
// o-code.adoc). A line that holds a `#`, a `[` or an O-word is parsed here
// (the reader only marks it); job/gcode_flow.hpp runs it.
//
// A line is read as LinuxCNC reads it: blanks and comments dropped, case
// folded. Values: numbers, `[expr]`, `#n`, `#<name>`, `#[expr]`, a sign
// before either, and the functions ABS ACOS ASIN ATAN[a]/[b] COS EXP FIX FUP
// LN ROUND SIN SQRT TAN EXISTS[#<name>] (degrees). Binary operators by
// precedence: ** ; * / MOD ; + - ; EQ NE GT GE LT LE ; AND OR XOR.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace kerf::job {

class GcodeParams;

// One node of an expression; children are indexes in ExprPool::nodes.
struct ExprNode {
  enum class Op : std::uint8_t {
    number, param, named, unary_minus, func, atan, exists,
    pow, mul, div, mod, add, sub, eq, ne, gt, ge, lt, le, and_, or_, xor_,
  };
  Op op = Op::number;
  std::uint8_t func = 0;  // Op::func: index in kFunctions
  double value = 0;       // Op::number
  int a = -1, b = -1;     // operands (Op::param: the number's expression)
  int depth = 1;          // of the tree under this node (bounded: evaluation recurses)
  std::string name;       // Op::named, Op::exists: folded, without < >
};

struct ExprPool {
  std::vector<ExprNode> nodes;
};

// A parsed line: its words (letter and value expression), its parameter
// assignments in order, or an O-word.
struct LineCode {
  struct Word {
    char letter = 0;  // upper case, or '$'
    int expr = -1;
  };
  struct Assign {
    int target = -1;  // a param/named node
    int expr = -1;
  };
  enum class Oword : std::uint8_t {
    none, sub, endsub, call, do_, while_, endwhile, if_, elseif, else_, endif, break_, continue_, repeat,
    endrepeat, return_,
  };
  std::vector<Word> words;
  std::vector<Assign> assigns;
  Oword oword = Oword::none;
  std::string oname;      // "100" or "<name>" (folded)
  std::vector<int> args;  // the O-word's [expr]s (call: all its arguments)
};

const char* oword_name(LineCode::Oword o);

// Parses one line (its text as read). False with a reason.
bool parse_line(std::string_view text, ExprPool& pool, LineCode& out, std::string& reason);

// Evaluates node `n`. False with a reason (division by zero, an unset named
// parameter, a function's argument out of its domain, ...).
bool eval_expr(const ExprPool& pool, int n, GcodeParams& params, double& out, std::string& reason);

}  // namespace kerf::job
