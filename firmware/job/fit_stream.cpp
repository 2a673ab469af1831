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
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "job/fit_stream.hpp"

#include "job/check_fit.hpp"
#include "job/fit_fixed.hpp"
#include "io/options.hpp"
#include "job/point_stream.hpp"
#include "io/fit_output.hpp"
#include "kerf/core/fixed_convert.hpp"
#include "kerf/fit/stream.hpp"
#include "kerf/fit/stream_band.hpp"

namespace kerf::job {

using io::kExitFailure;
using io::kExitOk;
using io::kExitUsage;

namespace {

// The largest window; the buffers are sized for it once, but only the pages
// the window actually uses are ever touched.
constexpr std::uint32_t kMaxWindow = 1u << 16;
using Window = fit::PointWindow<double, kMaxWindow>;
using BandWindow = fit::BandWindow<double, kMaxWindow>;
using FixedWindow = fit::PointWindow<Fixed, kMaxWindow>;
using FixedBandWindow = fit::BandWindow<Fixed, kMaxWindow>;

// a + b, built by += (armhf GCC 12 warns falsely on "literal" + string&&).
std::string join(const char* a, const std::string& b) {
  std::string s = a;
  s += b;
  return s;
}

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
    error = "--window: expected " + range + ", got " + io::quoted(text);
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
// A kerf::Fixed piece is written as `kerf fit --numeric fixed` writes it:
// its ends are the input's points (as read, in double: the last `recent` of
// them are kept), its centre converted. Each piece first passes the check
// `kerf fit` runs before it writes (job/check_fit.hpp) on its own points;
// a piece that fails it is not written and stops the stream.
struct PieceWriter {
  double max_error = 0.0;
  double tol = 0.0;        // the widest width asked for
  double allowance = 0.0;  // fixed point: the documented quantization
  double biggest = 0.0;    // the largest |coordinate| read so far
  int digits = io::kDigits;
  bool failed = false;
  std::string bad;  // why a piece failed its check
  std::vector<Vec2<double>> recent;  // input point k at k % size (the window and more)
  std::vector<Vec2<double>> span;    // one piece's points (capacity reserved up front)
  std::uint64_t seen = 0;
  void reserve(std::uint32_t window) {
    recent.resize(std::size_t{window} + 8);
    span.reserve(recent.size());
  }
  void saw(Vec2<double> p) {
    biggest = std::fmax(biggest, std::fmax(std::fabs(p.x), std::fabs(p.y)));
    recent[seen % recent.size()] = p;
    ++seen;
  }
  bool checked(const fit::Piece<double>& piece) {
    span.clear();
    for (std::uint64_t k = piece.first; k <= piece.last; ++k) span.push_back(recent[k % recent.size()]);
    fit::Piece<double> local = piece;
    local.first = 0;
    local.last = piece.last - piece.first;
    const std::string why = check_fit(Span<const Vec2<double>>(span.data(), span.size()),
                                      Span<const fit::Piece<double>>(&local, 1), tol + allowance);
    if (why.empty()) return true;
    bad = "piece " + std::to_string(piece.first) + ".." + std::to_string(piece.last) + ": " + why;
    return false;
  }
  void operator()(const fit::Piece<Fixed>& f, bool forced_end) {
    auto back = [](Vec2<Fixed> v) { return Vec2<double>{to_double(v.x), to_double(v.y)}; };
    const Vec2<double> a = recent[f.first % recent.size()];
    const Vec2<double> b = recent[f.last % recent.size()];
    const Segment<double> s{f.segment.kind, a, b, back(f.segment.centre), f.segment.dir};
    (*this)(fit::Piece<double>{f.first, f.last, s, to_double(f.error)}, forced_end);
  }
  void operator()(const fit::Piece<double>& piece, bool) {
    if (failed) return;
    if (!checked(piece)) {
      failed = true;
      return;
    }
    digits = std::max(digits, io::coordinate_digits(Span<const fit::Piece<double>>(&piece, 1), tol));
    const std::string line = io::esgi_piece_line(piece.segment, biggest * 1e-12, digits);
    if (std::fputs(line.c_str(), stdout) < 0 || std::fflush(stdout) != 0) failed = true;
    if (piece.error > max_error) max_error = piece.error;
  }
};

struct StreamSetup {
  std::uint32_t window = 0;
  bool fixed = false;
  double extent = 0.0;  // 0: none given
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
    return io::usage_error("--tol: required (or give both --tol-left and --tol-right)");
  if (!opts.tol.empty() && !io::parse_length("--tol", opts.tol, false, st.tol, error))
    return io::usage_error(error);
  st.left = st.right = st.tol;
  if (!opts.tol_left.empty() && !io::parse_length("--tol-left", opts.tol_left, true, st.left, error))
    return io::usage_error(error);
  if (!opts.tol_right.empty() && !io::parse_length("--tol-right", opts.tol_right, true, st.right, error))
    return io::usage_error(error);
  if (!(st.left + st.right > 0.0)) return io::usage_error("--tol-left and --tol-right: both are 0");
  return kExitOk;
}

int check_stream_options(const FitOptions& opts, std::optional<Criterion> criterion, std::optional<Numeric> numeric,
                         StreamSetup& st) {
  std::string error;
  if (!opts.stream) return io::usage_error("--window needs --stream");
  if (!parse_window(opts.window, st.window, error)) return io::usage_error(error);
  if (criterion != Criterion::vertex && criterion != Criterion::band)
    return io::usage_error("--stream: fits by the vertex or band criterion, not " +
                           io::quoted(opts.criterion));
  st.band = criterion == Criterion::band;
  if (!opts.pieces.empty())
    return io::usage_error("--stream: needs --tol; a piece budget (--pieces) needs the whole input");
  if (!numeric) return io::usage_error(unknown_numeric(opts.numeric));
  st.fixed = numeric == Numeric::fixed;
  if (!opts.extent.empty() && !io::parse_length("--extent", opts.extent, false, st.extent, error))
    return io::usage_error(error);
  if (st.fixed && opts.extent.empty())
    return io::usage_error("--stream --numeric fixed: needs --extent E (the largest |x| or |y| of the input, mm)");
  if (st.fixed && st.extent >= kFixedLimit)
    return io::usage_error("--extent: out of the fixed-point fit's range (< 2^30 = 1073741824)");
  if (opts.tie_break == "smallest")
    return io::usage_error("--tie-break smallest: needs the whole input (--stream writes --tie-break none)");
  if (!opts.tie_break.empty() && opts.tie_break != "none")
    return io::usage_error(join("--tie-break: expected smallest or none, got ", io::quoted(opts.tie_break)));
  if (opts.format != "esgi") return io::usage_error("--stream: writes the esgi format only");
  if (opts.output != "-")
    return io::usage_error("--stream: writes to stdout as it goes (an -o file could not be written atomically)");
  if (!opts.feed.empty()) return io::usage_error("--stream: --feed is for --format gcode");
  if (opts.method == "optimal") st.method = fit::Method::optimal;
  else if (opts.method == "esgi-max") st.method = fit::Method::esgi_max;
  else if (opts.method == "esgi-mean") st.method = fit::Method::esgi_mean;
  else
    return io::usage_error("--method: unknown method " + io::quoted(opts.method) +
                           " (expected optimal, esgi-max or esgi-mean)");
  if (st.band) {
    if (st.method != fit::Method::optimal)
      return io::usage_error("--method: " + io::quoted(opts.method) +
                             " is a vertex-criterion rule; --criterion band is always optimal");
    return check_band_sides(opts, st);
  }
  if (!opts.tol_left.empty() || !opts.tol_right.empty())
    return io::usage_error("--tol-left and --tol-right need --criterion band");
  if (opts.tol.empty()) return io::usage_error("--tol: required");
  if (!io::parse_length("--tol", opts.tol, false, st.tol, error)) return io::usage_error(error);
  return kExitOk;
}

// Feeds the points to w (started) and writes the pieces; the exit code.
template <class W>
int run_window(W& w, PointStream& in, const char* criterion, const std::string& method,
               std::uint32_t window, double tol, const std::string& tol_text, double extent) {
  using S = typename W::Value;
  std::printf("# kerf fit: criterion %s, method %s%s, stream, window %u\n# tol %s\n", criterion,
              method.c_str(), std::is_same_v<S, Fixed> ? ", numeric fixed" : "", window,
              tol_text.c_str());
  PieceWriter out;  // its buffers allocated before any point
  out.tol = tol;
  out.reserve(window);
  if (std::is_same_v<S, Fixed>) {
    const Vec2<double> corner{extent, extent};
    out.allowance = fixed_fit_slack(Span<const Vec2<double>>(&corner, 1));
  }
  Vec2<double> p;
  for (;;) {
    const PointStream::Next got = in.next(p);
    if (got == PointStream::Next::end) break;
    if (got == PointStream::Next::point) out.saw(p);
    Status s = Status::invalid_argument;
    const bool beyond = got == PointStream::Next::point && extent > 0.0 &&
                        (std::fabs(p.x) > extent || std::fabs(p.y) > extent);
    if (got != PointStream::Next::error && !beyond) {
      if constexpr (std::is_same_v<S, Fixed>)
        s = w.push(Vec2<Fixed>{fixed_from_double(p.x), fixed_from_double(p.y)}, out);
      else
        s = w.push(p, out);
    }
    if (got == PointStream::Next::error || s != Status::ok) {
      const std::string why = got == PointStream::Next::error ? in.reason()
                              : beyond ? join("a coordinate beyond --extent ", io::format_number(extent))
                                       : std::string(to_string(s));
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
  if (!out.bad.empty()) {  // a fitter bug or numeric breakdown: as kerf fit, never written
    std::fflush(stdout);
    std::fprintf(stderr,
                 "kerf: %s: internal error: a streamed fit fails its own check (%s); the pieces "
                 "before it are written\n",
                 in.file().c_str(), out.bad.c_str());
    return kExitFailure;
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
                        std::to_string(st.forced) + " forced commits, reach " + std::to_string(st.reach);
  if (in.duplicates() > 0)
    summary += ", dropped " + std::to_string(in.duplicates()) + " duplicate points";
  std::fprintf(stderr, "%s\n", summary.c_str());
  return kExitOk;
}

// Starts w (criterion set up) in st's frame: --extent, when given.
template <class W>
bool scale(W& w, const StreamSetup& st) {
  if (st.extent <= 0.0) return true;
  using S = typename W::Value;
  if constexpr (std::is_same_v<S, Fixed>) return w.scale_for(fixed_from_double(st.extent)) == Status::ok;
  else return w.scale_for(st.extent) == Status::ok;
}

template <class S>
S scalar(double v) {
  if constexpr (std::is_same_v<S, Fixed>) return fixed_from_double(v);
  else return v;
}

template <class W>
int run_band(const FitOptions& opts, const StreamSetup& st, PointStream& in) {
  using S = typename W::Value;
  const std::unique_ptr<W> w(new W);  // before any point: the only heap the fit uses
  if (w->start(scalar<S>(st.left), scalar<S>(st.right), st.window) != Status::ok)
    return io::usage_error(join("--window: the band criterion needs at least ", std::to_string(W::kMinWindow)));
  if (!scale(*w, st)) return io::usage_error("--extent: expected a length > 0");
  const double widest = std::max(st.left, st.right);
  return run_window(*w, in, "band", opts.method, st.window, widest, io::format_number(widest), st.extent);
}

template <class W>
int run_vertex(const FitOptions& opts, const StreamSetup& st, PointStream& in) {
  using S = typename W::Value;
  const std::unique_ptr<W> w(new W);
  if (w->start(scalar<S>(st.tol), st.method, st.window) != Status::ok)
    return io::usage_error(join("--window: the vertex criterion needs at least ", std::to_string(W::kMinWindow)));
  if (!scale(*w, st)) return io::usage_error("--extent: expected a length > 0");
  return run_window(*w, in, "vertex", opts.method, st.window, st.tol, io::format_number(st.tol), st.extent);
}

// --numeric fixed: a tol the grid resolves at the extent (as kerf fit's).
bool fixed_tol_ok(const StreamSetup& st) {
  const Vec2<double> corner{st.extent, st.extent};
  const double finest = fixed_min_tol(Span<const Vec2<double>>(&corner, 1));
  const double tol = st.band ? std::max(st.left, st.right) : st.tol;
  if (tol >= finest) return true;
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "--tol: %.6g is finer than the fixed-point fit resolves at --extent %.6g (at least "
                "%.3g; or use --numeric double)",
                tol, st.extent, finest);
  io::usage_error(buf);
  return false;
}

}  // namespace

int run_fit_stream(const FitOptions& opts, std::optional<Criterion> criterion, std::optional<Numeric> numeric) {
  StreamSetup st;
  if (const int rc = check_stream_options(opts, criterion, numeric, st); rc != kExitOk) return rc;
  if (st.fixed && !fixed_tol_ok(st)) return kExitUsage;

  PointStream in;
  if (!in.open(opts.file)) {
    std::fprintf(stderr, "kerf: %s: %s\n", opts.file.c_str(), in.reason().c_str());
    return kExitUsage;
  }
  if (st.band)
    return st.fixed ? run_band<FixedBandWindow>(opts, st, in) : run_band<BandWindow>(opts, st, in);
  return st.fixed ? run_vertex<FixedWindow>(opts, st, in) : run_vertex<Window>(opts, st, in);
}

}  // namespace kerf::job
