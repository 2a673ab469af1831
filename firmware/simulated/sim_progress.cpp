#include "simulated/sim_progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <utility>

namespace kerf::simulated {

SimProgressLine::SimProgressLine(PathLookup path_of, Totals totals)
    : path_of_(std::move(path_of)), totals_(std::move(totals)), on_(::isatty(STDERR_FILENO) == 1) {}

namespace {

// " of N", or nothing while N is not known.
void of(char* out, std::size_t size, std::size_t n) {
  if (n > 0 && n != control::JobSource::kUnknownCount) std::snprintf(out, size, " of %zu", n);
  else out[0] = '\0';
}

}  // namespace

void SimProgressLine::show(const SimProgress& p) {
  if (!on_) return;
  shown_ = true;
  const double ratio = p.wall_s > 0.0 ? p.sim_s / p.wall_s : 0.0;
  std::size_t path = 0;
  if (p.segment >= 0 && path_of_ && path_of_(static_cast<std::size_t>(p.segment), path)) {
    std::size_t n_paths = 0, n_segments = 0;
    if (totals_) totals_(n_paths, n_segments);
    char paths[32], segments[32];
    of(paths, sizeof paths, n_paths);
    of(segments, sizeof segments, n_segments);
    std::fprintf(stderr, "\r\033[Kkerf sim: path %zu%s, segment %lld%s, %.1f s simulated, %.0fx real time", path + 1,
                 paths, static_cast<long long>(p.segment) + 1, segments, p.sim_s, ratio);
  } else {
    std::fprintf(stderr, "\r\033[Kkerf sim: between segments, %.1f s simulated, %.0fx real time", p.sim_s, ratio);
  }
  std::fflush(stderr);
}

void SimProgressLine::clear() {
  if (shown_) std::fprintf(stderr, "\r\033[K");
  shown_ = false;
}

}  // namespace kerf::simulated
