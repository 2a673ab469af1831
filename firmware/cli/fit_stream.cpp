// `kerf fit --stream --window N`: the vertex-criterion fit of one path read
// line by line, each piece written (and flushed) as soon as it is decided,
// in memory fixed by the window (core/include/kerf/fit/stream.hpp).
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "cli/fit_command.hpp"
#include "cli/options.hpp"
#include "cli/point_stream.hpp"
#include "io/fit_output.hpp"
#include "kerf/fit/stream.hpp"
#include "kerf/fit/stream_band.hpp"

namespace kerf::cli {

namespace {

// The largest window; the buffers are sized for it once, but only the pages
// the window actually uses are ever touched.
constexpr std::uint32_t kMaxWindow = 1u << 16;
using Window = fit::PointWindow<double, kMaxWindow>;
using BandWindow = fit::BandWindow<double, kMaxWindow>;

bool parse_window(const std::string& text, std::uint32_t& out, std::string& error) {
  const std::string range = "a whole number from 4 to " + std::to_string(kMaxWindow);
  if (text.empty()) {
    error = "--window: required with --stream (" + range + ")";
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (text[0] < '0' || text[0] > '9' || *end != '\0' || errno == ERANGE || v < 4 ||
      v > kMaxWindow) {
    error = "--window: expected " + range + ", got " + quoted(text);
    return false;
  }
  out = static_cast<std::uint32_t>(v);
  return true;
}

// Writes one piece as `kerf fit` writes it in the esgi format, and flushes
// it. The number format is the whole-input writer's (io/fit_output.hpp),
// with what it takes from the whole input taken from the input so far: the
// resolution from the largest coordinate read, the digits the largest over
// the pieces written. Where the rest of the input changes neither (always,
// for coordinates below 1e6 mm and tol >= 1e-3 mm), the lines are the same.
struct PieceWriter {
  double max_error = 0.0;
  double tol = 0.0;      // the widest width asked for
  double biggest = 0.0;  // the largest |coordinate| read so far
  int digits = io::kDigits;
  bool failed = false;
  void saw(Vec2<double> p) { biggest = std::fmax(biggest, std::fmax(std::fabs(p.x), std::fabs(p.y))); }
  void operator()(const fit::Piece<double>& piece, bool) {
    digits = std::max(digits, io::coordinate_digits(Span<const fit::Piece<double>>(&piece, 1), tol));
    const std::string line = io::esgi_piece_line(piece.segment, biggest * 1e-12, digits);
    if (std::fputs(line.c_str(), stdout) < 0 || std::fflush(stdout) != 0) failed = true;
    if (piece.error > max_error) max_error = piece.error;
  }
};

struct StreamSetup {
  std::uint32_t window = 0;
  fit::Method method{};
  bool band = false;
  double tol = 0.0;    // vertex
  double left = 0.0;   // band
  double right = 0.0;
};

// The band's two sides: --tol-left / --tol-right, each defaulting to --tol.
int check_band_sides(const FitOptions& opts, StreamSetup& st) {
  std::string error;
  if (opts.tol.empty() && (opts.tol_left.empty() || opts.tol_right.empty()))
    return usage_error("--tol: required (or give both --tol-left and --tol-right)");
  if (!opts.tol.empty() && !parse_length("--tol", opts.tol, false, st.tol, error))
    return usage_error(error);
  st.left = st.right = st.tol;
  if (!opts.tol_left.empty() && !parse_length("--tol-left", opts.tol_left, true, st.left, error))
    return usage_error(error);
  if (!opts.tol_right.empty() && !parse_length("--tol-right", opts.tol_right, true, st.right, error))
    return usage_error(error);
  if (!(st.left + st.right > 0.0)) return usage_error("--tol-left and --tol-right: both are 0");
  return kExitOk;
}

int check_stream_options(const FitOptions& opts, StreamSetup& st) {
  std::string error;
  if (!opts.stream) return usage_error("--window needs --stream");
  if (!parse_window(opts.window, st.window, error)) return usage_error(error);
  if (opts.criterion != "vertex" && opts.criterion != "band")
    return usage_error("--stream: fits by the vertex or band criterion, not " +
                       quoted(opts.criterion));
  st.band = opts.criterion == "band";
  if (!opts.pieces.empty())
    return usage_error("--stream: needs --tol; a piece budget (--pieces) needs the whole input");
  if (opts.numeric != "double") return usage_error("--stream: runs in double only");
  if (opts.tie_break == "smallest")
    return usage_error("--tie-break smallest: needs the whole input (--stream writes --tie-break none)");
  if (!opts.tie_break.empty() && opts.tie_break != "none")
    return usage_error("--tie-break: expected smallest or none, got " + quoted(opts.tie_break));
  if (opts.format != "esgi") return usage_error("--stream: writes the esgi format only");
  if (opts.output != "-")
    return usage_error("--stream: writes to stdout as it goes (an -o file could not be written atomically)");
  if (!opts.feed.empty()) return usage_error("--stream: --feed is for --format gcode");
  if (opts.method == "optimal") st.method = fit::Method::optimal;
  else if (opts.method == "esgi-max") st.method = fit::Method::esgi_max;
  else if (opts.method == "esgi-mean") st.method = fit::Method::esgi_mean;
  else
    return usage_error("--method: unknown method " + quoted(opts.method) +
                       " (expected optimal, esgi-max or esgi-mean)");
  if (st.band) {
    if (st.method != fit::Method::optimal)
      return usage_error("--method: " + quoted(opts.method) +
                         " is a vertex-criterion rule; --criterion band is always optimal");
    return check_band_sides(opts, st);
  }
  if (!opts.tol_left.empty() || !opts.tol_right.empty())
    return usage_error("--tol-left and --tol-right need --criterion band");
  if (opts.tol.empty()) return usage_error("--tol: required");
  if (!parse_length("--tol", opts.tol, false, st.tol, error)) return usage_error(error);
  return kExitOk;
}

// Feeds the points to w (started) and writes the pieces; the exit code.
template <class W>
int run_window(W& w, PointStream& in, const char* criterion, const std::string& method,
               std::uint32_t window, double tol, const std::string& tol_text) {
  std::printf("# kerf fit: criterion %s, method %s, stream, window %u\n# tol %s\n", criterion,
              method.c_str(), window, tol_text.c_str());
  PieceWriter out;
  out.tol = tol;
  Vec2<double> p;
  for (;;) {
    const PointStream::Next got = in.next(p);
    if (got == PointStream::Next::end) break;
    if (got == PointStream::Next::point) out.saw(p);
    const Status s = got == PointStream::Next::error ? Status::invalid_argument : w.push(p, out);
    if (got == PointStream::Next::error || s != Status::ok) {
      const std::string why = got == PointStream::Next::error ? in.reason() : to_string(s);
      const unsigned long long done = w.stats().pieces;
      std::fprintf(stderr, "%s:%zu: %s (%llu %s before it already written)\n", in.file().c_str(),
                   in.line(), why.c_str(), done, done == 1 ? "piece" : "pieces");
      return kExitUsage;
    }
    if (out.failed) break;
  }
  if (!out.failed && w.finish(out) != Status::ok) {
    std::fprintf(stderr, "%s: fewer than two distinct points (got %llu)\n", in.file().c_str(),
                 static_cast<unsigned long long>(w.stats().points));
    return kExitUsage;
  }
  const fit::StreamStats& st = w.stats();
  std::printf("# max error %s\n# Number of arcs is Narc = %llu\n",
              io::format_number(out.max_error).c_str(),
              static_cast<unsigned long long>(st.pieces));
  if (out.failed || std::fflush(stdout) != 0) {
    std::fprintf(stderr, "kerf: cannot write output: %s\n", std::strerror(errno));
    return kExitFailure;
  }
  if (!std::isfinite(out.max_error)) {  // stream_band.hpp: a region refused a chosen pair
    std::fprintf(stderr, "kerf: %s: internal error: a streamed piece failed its band test\n",
                 in.file().c_str());
    return kExitFailure;
  }
  std::string summary = "kerf: " + in.file() + ": " + std::to_string(st.points) + " points, " +
                        std::to_string(st.pieces) + (st.pieces == 1 ? " piece" : " pieces") +
                        ", max error " + io::format_number(out.max_error) + ", window " +
                        std::to_string(window) + " (most held " + std::to_string(st.peak) + "), " +
                        std::to_string(st.forced) + " forced commits";
  if (in.duplicates() > 0)
    summary += ", dropped " + std::to_string(in.duplicates()) + " duplicate points";
  std::fprintf(stderr, "%s\n", summary.c_str());
  return kExitOk;
}

}  // namespace

int run_fit_stream(const FitOptions& opts) {
  StreamSetup st;
  if (const int rc = check_stream_options(opts, st); rc != kExitOk) return rc;

  PointStream in;
  if (!in.open(opts.file)) {
    std::fprintf(stderr, "kerf: %s: %s\n", opts.file.c_str(), in.reason().c_str());
    return kExitUsage;
  }
  // Allocated once, before any point: the only heap the fit uses.
  if (st.band) {
    const std::unique_ptr<BandWindow> w(new BandWindow);
    if (w->start(st.left, st.right, st.window) != Status::ok)
      return usage_error("--window: the band criterion needs at least " +
                         std::to_string(BandWindow::kMinWindow));
    const double widest = std::max(st.left, st.right);
    return run_window(*w, in, "band", opts.method, st.window, widest, io::format_number(widest));
  }
  const std::unique_ptr<Window> w(new Window);
  if (w->start(st.tol, st.method, st.window) != Status::ok)
    return usage_error("--window: the vertex criterion needs at least 4");
  return run_window(*w, in, "vertex", opts.method, st.window, st.tol, io::format_number(st.tol));
}

}  // namespace kerf::cli
