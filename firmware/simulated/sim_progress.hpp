// `kerf sim`'s progress line on a terminal, as `kerf weld` has one: the path
// and segment being run, the simulated time and its ratio to the wall time,
// redrawn in place on stderr. Off (and silent) when stderr is not a TTY, so
// piped and tested output never changes.
#pragma once

#include <cstddef>
#include <vector>

#include "simulated/sim_machine.hpp"

namespace kerf::simulated {

class SimProgressLine {
 public:
  SimProgressLine(const std::vector<std::size_t>& piece_path, std::size_t paths);
  bool on() const { return on_; }
  void show(const SimProgress& p);
  void clear();  // erases the line, if one was drawn

 private:
  const std::vector<std::size_t>& piece_path_;
  std::size_t paths_;
  bool on_;
  bool shown_ = false;
};

}  // namespace kerf::simulated
