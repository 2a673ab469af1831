// The journal's on-disk records: one text line each, readable with `cat`,
// ending in " #<crc32 hex>\n" so that a torn or corrupt line is detected.
//
//   kerf-journal 1 job=00ab12cd34ef5678 segments=42     #1a2b3c4d   fixed width, offset 0
//   cut 18 12.345678 -3.250000                          #5e6f7a8b   fixed width, offset kSlotOffset
//   run 1                                               appended records from kAppendOffset:
//   done 0                                              one per completed segment
//   ...
//   finished
//
// The two fixed-width lines are padded with spaces before the checksum so
// that the cut slot can be overwritten in place; the checksum covers the text
// without the padding.
#pragma once

#include <cstddef>
#include <cstdint>

namespace kerf::control::journal_record {

inline constexpr std::size_t kFixedWidth = 80;  // header and cut slot, '\n' included
inline constexpr std::size_t kSlotOffset = kFixedWidth;
inline constexpr std::size_t kAppendOffset = 2 * kFixedWidth;
inline constexpr std::size_t kMaxLine = kFixedWidth;  // no record is longer
inline constexpr int kVersion = 1;

std::uint32_t crc32(const char* data, std::size_t n);

// Writes `text` (length n) as a record line into out (capacity kMaxLine):
// padded to `width` when width > 0. Returns the line length, 0 when it does
// not fit. Does not allocate (the cut slot is written every cycle).
std::size_t encode(const char* text, std::size_t n, std::size_t width, char* out);

// Checks one line (up to and including its '\n'); on success `text` and
// `text_len` give the record text without padding and checksum.
bool decode(const char* line, std::size_t n, const char*& text, std::size_t& text_len);

}  // namespace kerf::control::journal_record
