// Generated G-code piped through the `kerf weld` command (tests/weld's scale
// test and tests/bench's streaming bench): the job is written into kerf's
// stdin as kerf reads it, so that no large file is ever made.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace kerf_test {

// Appends shape k of a generated job, kShapeLines lines: a rapid, M3, a
// 24-point circle of G1 moves (radius 1, 3 decimals, F on the first) that
// welds into two arcs at tol 0.025, M5, a comment, and rapids over a row of
// dots (lines passed through; they keep the weld's share of the time as in
// a real job, so that 1e7 lines take seconds).
inline constexpr std::size_t kShapeLines = 200;
void append_shape(std::string& out, std::uint64_t k);

struct PipeRun {
  bool ok = false;          // kerf exited 0
  long max_rss_kb = 0;      // kerf's peak RSS (wait4)
  double seconds = 0;       // spawn to exit
  double first_output = 0;  // spawn to the first byte of G-code out
  double input_written = 0; // spawn to the last byte of the job written into kerf
  std::size_t lines = 0;    // written
  std::size_t out_bytes = 0;
  std::string out;          // the G-code out, when kept
  std::string err;          // kerf's stderr (the summary)
};

// Runs `kerf weld --tol 0.025 --threads T - -` on `lines` lines (whole
// shapes, at least `lines`); keeps the output when keep_output.
PipeRun weld_pipe(const std::string& kerf, std::uint64_t lines, int threads, bool keep_output);

}  // namespace kerf_test
