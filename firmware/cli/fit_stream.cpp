// `kerf fit --stream --window N`: the vertex-criterion fit of one path read
// line by line, each piece written (and flushed) as soon as it is decided,
// in memory fixed by the window (core/include/kerf/fit/stream.hpp).
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "cli/fit_command.hpp"
#include "cli/options.hpp"
#include "cli/point_stream.hpp"
#include "io/fit_output.hpp"
#include "kerf/fit/stream.hpp"

namespace kerf::cli {

namespace {

// The largest window; the buffers are sized for it once, but only the pages
// the window actually uses are ever touched.
constexpr std::uint32_t kMaxWindow = 1u << 16;
using Window = fit::PointWindow<double, kMaxWindow>;

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

std::string point_text(Vec2<double> p) {
  return "(" + io::format_number(p.x) + "," + io::format_number(p.y) + ")";
}

// Writes one piece in the esgi format's line form, and flushes it.
struct PieceWriter {
  double max_error = 0.0;
  bool failed = false;
  void operator()(const fit::Piece<double>& piece, bool) {
    const Segment<double>& s = piece.segment;
    std::string line = s.is_arc() ? "A " : "L ";
    line += point_text(s.start) + ' ' + point_text(s.end);
    if (s.is_arc()) line += ' ' + point_text(s.centre) + (s.dir > 0 ? " 1" : " -1");
    line += '\n';
    if (std::fputs(line.c_str(), stdout) < 0 || std::fflush(stdout) != 0) failed = true;
    if (piece.error > max_error) max_error = piece.error;
  }
};

int check_stream_options(const FitOptions& opts, std::uint32_t& window, fit::Method& method,
                         double& tol) {
  std::string error;
  if (!opts.stream) return usage_error("--window needs --stream");
  if (!parse_window(opts.window, window, error)) return usage_error(error);
  if (opts.criterion != "vertex")
    return usage_error("--stream: fits by the vertex criterion only, not " +
                       quoted(opts.criterion));
  if (!opts.pieces.empty())
    return usage_error("--stream: needs --tol; a piece budget (--pieces) needs the whole input");
  if (opts.numeric != "double") return usage_error("--stream: runs in double only");
  if (opts.format != "esgi") return usage_error("--stream: writes the esgi format only");
  if (opts.method == "optimal") method = fit::Method::optimal;
  else if (opts.method == "esgi-max") method = fit::Method::esgi_max;
  else if (opts.method == "esgi-mean") method = fit::Method::esgi_mean;
  else
    return usage_error("--method: unknown method " + quoted(opts.method) +
                       " (expected optimal, esgi-max or esgi-mean)");
  if (opts.tol.empty()) return usage_error("--tol: required");
  if (!parse_length("--tol", opts.tol, false, tol, error)) return usage_error(error);
  return kExitOk;
}

}  // namespace

int run_fit_stream(const FitOptions& opts) {
  std::uint32_t window = 0;
  fit::Method method{};
  double tol = 0.0;
  if (const int rc = check_stream_options(opts, window, method, tol); rc != kExitOk) return rc;

  PointStream in;
  if (!in.open(opts.file)) {
    std::fprintf(stderr, "kerf: %s: %s\n", opts.file.c_str(), in.reason().c_str());
    return kExitUsage;
  }
  // Allocated once, before any point: the only heap the fit uses.
  const std::unique_ptr<Window> w(new Window);
  if (w->start(tol, method, window) != Status::ok) return usage_error("--tol: invalid");

  std::printf("# kerf fit: criterion vertex, method %s, stream, window %u\n# tol %s\n",
              opts.method.c_str(), window, io::format_number(tol).c_str());
  PieceWriter out;
  Vec2<double> p;
  for (;;) {
    const PointStream::Next got = in.next(p);
    if (got == PointStream::Next::end) break;
    const Status s = got == PointStream::Next::error ? Status::invalid_argument : w->push(p, out);
    if (got == PointStream::Next::error || s != Status::ok) {
      const std::string why = got == PointStream::Next::error ? in.reason() : to_string(s);
      const unsigned long long done = w->stats().pieces;
      std::fprintf(stderr, "%s:%zu: %s (%llu %s before it already written)\n", in.file().c_str(),
                   in.line(), why.c_str(), done, done == 1 ? "piece" : "pieces");
      return kExitUsage;
    }
    if (out.failed) break;
  }
  if (!out.failed && w->finish(out) != Status::ok) {
    std::fprintf(stderr, "%s: fewer than two distinct points (got %llu)\n", in.file().c_str(),
                 static_cast<unsigned long long>(w->stats().points));
    return kExitUsage;
  }
  const fit::StreamStats& st = w->stats();
  std::printf("# max error %s\n# Number of arcs is Narc = %llu\n",
              io::format_number(out.max_error).c_str(),
              static_cast<unsigned long long>(st.pieces));
  if (out.failed || std::fflush(stdout) != 0) {
    std::fprintf(stderr, "kerf: cannot write output: %s\n", std::strerror(errno));
    return kExitFailure;
  }
  std::string summary = "kerf: " + in.file() + ": " + std::to_string(st.points) + " points, " +
                        std::to_string(st.pieces) + (st.pieces == 1 ? " piece" : " pieces") +
                        ", max error " +
                        io::format_number(out.max_error) + ", window " + std::to_string(window) +
                        " (most held " + std::to_string(st.peak) + "), " +
                        std::to_string(st.forced) + " forced commits";
  if (in.duplicates() > 0)
    summary += ", dropped " + std::to_string(in.duplicates()) + " duplicate points";
  std::fprintf(stderr, "%s\n", summary.c_str());
  return kExitOk;
}

}  // namespace kerf::cli
