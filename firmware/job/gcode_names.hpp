// How the interpreter names a G-code word in its messages: a value as %g,
// a G or M code from its tenths (G64, G59.1).
#pragma once

#include <cstdio>
#include <string>

namespace kerf::job {

struct WordValue {
  char text[32];
  operator const char*() const { return text; }
};

inline WordValue word_value(double v) {
  WordValue w;
  std::snprintf(w.text, sizeof w.text, "%g", v);
  return w;
}

inline std::string code_name(char letter, int c10) {
  char buf[24];
  if (c10 % 10 == 0) std::snprintf(buf, sizeof buf, "%c%d", letter, c10 / 10);
  else std::snprintf(buf, sizeof buf, "%c%d.%d", letter, c10 / 10, c10 % 10);
  return buf;
}

}  // namespace kerf::job
