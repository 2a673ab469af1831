#include "simulated/sim_progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace kerf::simulated {

SimProgressLine::SimProgressLine(const std::vector<std::size_t>& piece_path, std::size_t paths)
    : piece_path_(piece_path), paths_(paths), on_(::isatty(STDERR_FILENO) == 1) {}

void SimProgressLine::show(const SimProgress& p) {
  if (!on_) return;
  shown_ = true;
  const double ratio = p.wall_s > 0.0 ? p.sim_s / p.wall_s : 0.0;
  if (p.segment >= 0 && static_cast<std::size_t>(p.segment) < piece_path_.size())
    std::fprintf(stderr, "\r\033[Kkerf sim: path %zu of %zu, segment %lld of %zu, %.1f s simulated, %.0fx real time",
                 piece_path_[static_cast<std::size_t>(p.segment)] + 1, paths_, static_cast<long long>(p.segment) + 1,
                 piece_path_.size(), p.sim_s, ratio);
  else
    std::fprintf(stderr, "\r\033[Kkerf sim: between segments, %.1f s simulated, %.0fx real time", p.sim_s, ratio);
  std::fflush(stderr);
}

void SimProgressLine::clear() {
  if (shown_) std::fprintf(stderr, "\r\033[K");
  shown_ = false;
}

}  // namespace kerf::simulated
