// `kerf weld` on files (weld/weld.hpp: weld_file).
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "io/options.hpp"
#include "io/output_file.hpp"
#include "job/gcode_reader.hpp"
#include "weld/weld.hpp"

namespace kerf::weld {

using io::kExitFailure;
using io::kExitOk;
using io::kExitUsage;

int weld_file(const std::string& in, const std::string& out, WeldOptions w) {
  const auto t0 = std::chrono::steady_clock::now();
  const job::GcodeFile g = job::read_gcode(in);
  if (!g.ok) {
    std::fprintf(stderr, "kerf: %s\n", job::describe_error(g).c_str());
    return kExitUsage;
  }
  // Progress on a terminal only, at most five times a second.
  bool shown = false;
  auto last = std::chrono::steady_clock::now();
  if (::isatty(STDERR_FILENO) == 1 && g.blocks.size() > 20000) {
    w.progress = [&](std::size_t line, std::size_t lines) {
      const auto now = std::chrono::steady_clock::now();
      if (now - last < std::chrono::milliseconds(200)) return;
      last = now;
      shown = true;
      std::fprintf(stderr, "\rkerf weld: line %zu of %zu (%.0f%%)", line, lines,
                   100.0 * static_cast<double>(line) / static_cast<double>(lines));
    };
  }
  std::string text, error;
  WeldStats stats;
  const bool welded = weld_gcode(g, w, text, stats, error);
  if (shown) std::fprintf(stderr, "\r\033[K");  // clear the progress line
  if (!welded) {
    std::fprintf(stderr, "kerf: %s\n", error.c_str());
    return kExitFailure;
  }
  if (!io::write_output(out, text)) {
    std::fprintf(stderr, "kerf: %s: %s\n", out.c_str(), std::strerror(errno));
    return kExitFailure;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The summary goes to stdout, unless the G-code does.
  std::FILE* report = out == "-" ? stderr : stdout;
  std::fprintf(report,
               "input moves: %zu\noutput moves: %zu\narcs: %zu\nmax deviation: %.6f mm\n"
               "kept for rounding: %zu pieces\ntime: %.3f s (%.0f lines/s)\n",
               stats.input_moves, stats.output_moves, stats.arcs, stats.max_deviation_mm,
               stats.kept_pieces, seconds, seconds > 0 ? static_cast<double>(g.blocks.size()) / seconds : 0.0);
  return kExitOk;
}

}  // namespace kerf::weld
