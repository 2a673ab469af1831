// The independent toolpath reader's own evaluator (tests/support/toolpath_reader):
// runs a G-code program's parameters, expressions and O-word control flow and
// gives back the lines it runs, in order, as plain words. It shares no code
// with firmware/job: written from LinuxCNC's G-code reference (overview.adoc
// "Parameters" and "Expressions", o-code.adoc), short rather than fast.
//
// Values: #n (unset reads 0), #<name> (unset is an error), #<_hal[...]> (reads
// 0: a pin's value moves no XY), [expressions] with ** * / MOD + - EQ NE GT GE
// LT LE AND OR XOR, the functions ABS ACOS ASIN ATAN[]/[] COS EXP FIX FUP LN
// ROUND SIN SQRT TAN EXISTS. Flow: sub/endsub/return/call (same file),
// if/elseif/else/endif, while/endwhile, do/while, repeat/endrepeat, break,
// continue; at most 10 million lines run.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace kerf_test {

struct RunLine {
  std::size_t line = 0;  // 1-based, in the file
  std::string text;      // plain words (a line without # [ or O is given back as read)
};

// False with "LINE: reason" (also past `max_lines` lines run).
bool run_program(const std::string& text, std::vector<RunLine>& out, std::string& why,
                 std::size_t max_lines = 10'000'000);

}  // namespace kerf_test
