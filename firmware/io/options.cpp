#include "io/options.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace kerf::io {

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

int usage_error(const std::string& message) {
  std::fprintf(stderr, "kerf: %s\n", message.c_str());
  return kExitUsage;
}

bool parse_length(const std::string& name, const std::string& text, bool allow_zero, double& out,
                  std::string& error) {
  if (text.empty()) {
    error = name + ": required";
    return false;
  }
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  // strtod skips leading blanks; an option value must not have them either
  const bool blank = !text.empty() && std::isspace(static_cast<unsigned char>(text[0])) != 0;
  if (text.empty() || blank || end != text.c_str() + text.size()) {
    error = name + ": not a number: " + quoted(text);
    return false;
  }
  if (!std::isfinite(v)) {
    error = name + ": must be finite, got " + text;
    return false;
  }
  if (allow_zero ? !(v >= 0.0) : !(v > 0.0)) {
    error = name + (allow_zero ? ": must be >= 0, got " : ": must be > 0, got ") + text;
    return false;
  }
  out = v;
  return true;
}

bool parse_pieces(const std::string& text, std::uint32_t& pieces, std::string& error) {
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits) {
    error = "--pieces: must be a whole number >= 1, got " + quoted(text);
    return false;
  }
  const std::size_t nz = text.find_first_not_of('0');
  if (nz == std::string::npos) {
    error = "--pieces: must be >= 1, got " + text;
    return false;
  }
  if (text.size() - nz > 9) {  // up to 999999999, far beyond any point count
    error = "--pieces: too large, got " + text;
    return false;
  }
  pieces = static_cast<std::uint32_t>(std::strtoul(text.c_str() + nz, nullptr, 10));
  return true;
}

}  // namespace kerf::io
