// `kerf sim`'s progress line on a terminal, as `kerf weld` has one: the path
// and segment being run, the simulated time and its ratio to the wall time,
// redrawn in place on stderr. Off (and silent) when stderr is not a TTY, so
// piped and tested output never changes. It holds nothing of the job: the
// path of the running segment comes from a lookup (job_watch.hpp keeps the
// recent ones), the totals from the job source when it knows them (a
// stream: at its end; JobSource::kUnknownCount until then).
#pragma once

#include <cstddef>
#include <functional>

#include "simulated/sim_machine.hpp"

namespace kerf::simulated {

class SimProgressLine {
 public:
  // Job segment k's path into `path`; false if it is not known.
  using PathLookup = std::function<bool(std::size_t k, std::size_t& path)>;
  // The job's paths and segments, asked at each redraw.
  using Totals = std::function<void(std::size_t& paths, std::size_t& segments)>;
  SimProgressLine(PathLookup path_of, Totals totals);
  bool on() const { return on_; }
  void show(const SimProgress& p);
  void clear();  // erases the line, if one was drawn

 private:
  PathLookup path_of_;
  Totals totals_;
  bool on_;
  bool shown_ = false;
};

}  // namespace kerf::simulated
