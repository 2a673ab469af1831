#include "io/quote.hpp"

#include <cstdio>

namespace kerf::io {

std::string quote(std::string_view s) {
  constexpr std::size_t kMax = 40;
  std::string q = "\"";
  for (std::size_t i = 0; i < s.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '"' || c == '\\') {
      q += '\\';
      q += static_cast<char>(c);
    } else if (c >= 0x20 && c < 0x7f) {
      q += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(c));
      q += buf;
    }
  }
  if (s.size() > kMax) q += "...";
  q += '"';
  return q;
}

}  // namespace kerf::io
