// printf into a std::string, for the controller's reasons and action logs
// (short texts: at most 239 characters are kept).
#pragma once

#include <cstdarg>
#include <cstdio>
#include <string>

namespace kerf::control {

__attribute__((format(printf, 1, 2))) inline std::string format_text(const char* fmt, ...) {
  char buf[240];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, args);
  va_end(args);
  return buf;
}

}  // namespace kerf::control
