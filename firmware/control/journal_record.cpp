#include "control/journal_record.hpp"

#include <array>
#include <cstring>

namespace kerf::control::journal_record {

namespace {

// CRC-32 (IEEE 802.3, reflected, as zlib's crc32): the table is built at compile time.
constexpr std::array<std::uint32_t, 256> make_table() {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1u) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[i] = c;
  }
  return t;
}
constexpr auto kTable = make_table();

constexpr std::size_t kTrailer = 11;  // " #" + 8 hex digits + '\n'
constexpr char kHex[] = "0123456789abcdef";

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

}  // namespace

std::uint32_t crc32(const char* data, std::size_t n) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i)
    c = kTable[(c ^ static_cast<unsigned char>(data[i])) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::size_t encode(const char* text, std::size_t n, std::size_t width, char* out) {
  const std::size_t len = width > 0 ? width : n + kTrailer;
  if (n + kTrailer > len || len > kMaxLine) return 0;
  if (std::memchr(text, '\n', n) != nullptr || std::memchr(text, '#', n) != nullptr) return 0;
  std::memcpy(out, text, n);
  std::memset(out + n, ' ', len - n - kTrailer);
  char* t = out + len - kTrailer;
  t[0] = ' ';
  t[1] = '#';
  const std::uint32_t c = crc32(text, n);
  for (int k = 0; k < 8; ++k) t[2 + k] = kHex[(c >> (28 - 4 * k)) & 0xFu];
  t[10] = '\n';
  return len;
}

bool decode(const char* line, std::size_t n, const char*& text, std::size_t& text_len) {
  if (n < kTrailer + 1 || line[n - 1] != '\n') return false;
  const char* t = line + n - kTrailer;
  if (t[0] != ' ' || t[1] != '#') return false;
  std::uint32_t want = 0;
  for (int k = 0; k < 8; ++k) {
    const int v = hex_value(t[2 + k]);
    if (v < 0) return false;
    want = (want << 4) | static_cast<std::uint32_t>(v);
  }
  std::size_t len = n - kTrailer;
  while (len > 0 && line[len - 1] == ' ') --len;  // the fixed-width lines' padding
  if (len == 0 || crc32(line, len) != want) return false;
  text = line;
  text_len = len;
  return true;
}

}  // namespace kerf::control::journal_record
