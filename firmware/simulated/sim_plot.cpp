#include "simulated/sim_plot.hpp"

#include <algorithm>
#include <utility>

namespace kerf::simulated {

PlotKeeper::PlotKeeper(bool on, std::size_t max_points, std::size_t max_pieces)
    : on_(on), max_points_(max_points), max_pieces_(max_pieces) {}

bool PlotKeeper::add_points(std::size_t path, const Vec2<double>* points, std::size_t n) {
  if (!on_) return false;
  const std::size_t room = max_points_ - points_;
  const std::size_t take = std::min(n, room);
  points_left_out_ += n - take;
  if (take == 0) return false;
  if (plot_.paths.size() <= path) plot_.paths.resize(path + 1);
  plot_.paths[path].insert(plot_.paths[path].end(), points, points + take);
  points_ += take;
  return points_ < max_points_;
}

void PlotKeeper::add_piece(const Segment<double>& s, std::size_t path) {
  if (!on_) return;
  if (plot_.pieces.size() >= max_pieces_) {
    ++pieces_left_out_;
    return;
  }
  plot_.pieces.push_back(s);
  plot_.piece_path.push_back(path);
}

io::RunPlot PlotKeeper::take(const std::string& title) {
  io::RunPlot out = std::move(plot_);
  out.title = title;
  if (points_left_out_ > 0 || pieces_left_out_ > 0)
    out.title += "; the first " + std::to_string(points_) + " points and " + std::to_string(out.pieces.size()) +
                 " pieces drawn";
  plot_ = io::RunPlot{};
  return out;
}

}  // namespace kerf::simulated
