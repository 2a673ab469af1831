// `kerf weld` on files (weld/weld.hpp: weld_file), streamed part by part.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <algorithm>
#include <cstring>
#include <string>

#include "io/options.hpp"
#include "weld/weld.hpp"

namespace kerf::weld {

using io::kExitFailure;
using io::kExitOk;
using io::kExitUsage;

namespace {

// The output as it is written: "-" is stdout; a regular file (or a new one)
// is written to PATH.tmp and renamed over it at the end, or removed on a
// failure, so that no half file is left; anything else (/dev/null, a fifo)
// is written in place, never replaced. On stdout a failure after the first
// part leaves the parts written so far.
class Output {
 public:
  explicit Output(const std::string& path) : path_(path) {}
  ~Output() {
    if (f_ != nullptr && f_ != stdout) std::fclose(f_);
    if (!tmp_.empty()) std::remove(tmp_.c_str());
  }
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  bool open() {
    if (path_ == "-") return f_ = stdout, true;
    struct stat st {};
    if (::stat(path_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) return (f_ = std::fopen(path_.c_str(), "wb"));
    tmp_ = path_ + ".tmp";
    f_ = std::fopen(tmp_.c_str(), "wb");
    if (f_ == nullptr) tmp_.clear();
    return f_ != nullptr;
  }
  bool write(const std::string& text) {
    return std::fwrite(text.data(), 1, text.size(), f_) == text.size() && std::fflush(f_) == 0;
  }
  // Closes the output and renames the temp file over PATH.
  bool commit() {
    std::FILE* f = f_;
    f_ = nullptr;
    if (f == stdout) return std::fflush(f) == 0 && std::ferror(f) == 0;
    const bool ok = std::ferror(f) == 0;
    if (std::fclose(f) != 0 || !ok) return false;
    if (!tmp_.empty() && std::rename(tmp_.c_str(), path_.c_str()) != 0) return false;
    tmp_.clear();
    return true;
  }

 private:
  std::string path_, tmp_;
  std::FILE* f_ = nullptr;
};

}  // namespace

int weld_file(const std::string& in, const std::string& out, WeldOptions w) {
  const auto t0 = std::chrono::steady_clock::now();
  const bool use_stdin = in == "-";
  const std::string name = use_stdin ? "<stdin>" : in;
  std::FILE* f = use_stdin ? stdin : std::fopen(in.c_str(), "rb");
  if (f == nullptr) {
    std::fprintf(stderr, "kerf: %s: %s\n", name.c_str(), std::strerror(errno));
    return kExitUsage;
  }
  struct Close {
    std::FILE* f;
    ~Close() {
      if (f != stdin) std::fclose(f);
    }
  } close{f};
  StreamOptions so;
  std::string error;
  // A file larger than a part is read twice: first for its decimals (so that
  // the output is the whole-file weld's), its lines and its errors. A smaller
  // one is read in one part of its size (a part's buffer is written whole
  // before the read: 1 MiB of page faults cost a small file 0.6 ms).
  GcodeScan scan;
  const long size = !use_stdin && std::fseek(f, 0, SEEK_END) == 0 ? std::ftell(f) : -1;
  if (size >= 0 && static_cast<unsigned long>(size) < so.chunk_bytes)
    so.chunk_bytes = static_cast<std::size_t>(size) + 1;
  if (size > static_cast<long>(so.chunk_bytes)) {
    std::rewind(f);
    if (!scan_gcode(f, name, so.chunk_bytes, scan, error)) {
      std::fprintf(stderr, "kerf: %s\n", error.c_str());
      return kExitUsage;
    }
    if (w.decimals < 0) w.decimals = std::max<int>(3, static_cast<int>(scan.decimals));
  }
  if (!use_stdin) std::rewind(f);
  // Progress on a terminal only, at most five times a second.
  bool shown = false;
  auto last = std::chrono::steady_clock::now();
  if (::isatty(STDERR_FILENO) == 1) {
    w.progress = [&](std::size_t line) {
      const auto now = std::chrono::steady_clock::now();
      if (now - last < std::chrono::milliseconds(200) || now - t0 < std::chrono::milliseconds(500)) return;
      last = now;
      shown = true;
      if (scan.lines > 0)
        std::fprintf(stderr, "\rkerf weld: line %zu of %zu (%.0f%%)", line, scan.lines,
                     100.0 * static_cast<double>(line) / static_cast<double>(scan.lines));
      else
        std::fprintf(stderr, "\rkerf weld: line %zu", line);
    };
  }
  Output output(out);
  if (!output.open()) {
    std::fprintf(stderr, "kerf: %s: %s\n", out.c_str(), std::strerror(errno));
    return kExitFailure;
  }
  WeldStats stats;
  const StreamEnd end = weld_stream(
      f, name, [&](const std::string& text) { return output.write(text); }, w, so, stats, error);
  if (shown) std::fprintf(stderr, "\r\033[K");  // clear the progress line
  if (end == StreamEnd::bad_input || end == StreamEnd::fit_failed) {
    std::fprintf(stderr, "kerf: %s\n", error.c_str());
    return end == StreamEnd::bad_input ? kExitUsage : kExitFailure;
  }
  if (end == StreamEnd::write_failed || !output.commit()) {
    std::fprintf(stderr, "kerf: %s: %s\n", out.c_str(), std::strerror(errno));
    return kExitFailure;
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // The summary goes to stdout, unless the G-code does.
  std::FILE* report = out == "-" ? stderr : stdout;
  std::fprintf(report,
               "input moves: %zu\noutput moves: %zu\narcs: %zu\nmax deviation: %.6f mm\n"
               "kept for rounding: %zu pieces\nforced commits: %zu\ntime: %.3f s (%.0f lines/s)\n",
               stats.input_moves, stats.output_moves, stats.arcs, stats.max_deviation_mm,
               stats.kept_pieces, stats.forced_commits, seconds,
               seconds > 0 ? static_cast<double>(stats.lines) / seconds : 0.0);
  return kExitOk;
}

}  // namespace kerf::weld
