// The interpreter's meaning of one block (job/gcode_interp.hpp), block by
// block: what interpret() runs on a whole file and what the window reading
// (job/program_window.hpp) runs part by part. Its modal state (units,
// motion, feed, position, tool, material) lives here between blocks; the
// offsets, constructs and notes in the Interpretation it writes to.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <string>

#include "job/gcode_interp.hpp"

namespace kerf::job {

class BlockInterp {
 public:
  // `out.state` starts as `state`; `out` must outlive this.
  BlockInterp(const InterpSettings& settings, const MachineState& state, Interpretation& out);
  ~BlockInterp();
  BlockInterp(const BlockInterp&) = delete;
  BlockInterp& operator=(const BlockInterp&) = delete;

  // Runs one block whose words' values are computed (job/gcode_flow.hpp):
  // its canonical moves and actions are appended to out.canon. False with
  // the reason (without FILE:LINE).
  bool run(std::size_t line, std::span<const GWord> words, std::string& why);
  // M2/M30 ran: nothing after it runs.
  bool ended() const;
  // What #<_hal[plasmac.cut-feed-rate]> reads: the cut feed in the program's units.
  double hal_cut_feed() const;

 private:
  struct Interp;
  std::unique_ptr<Interp> impl_;
};

}  // namespace kerf::job
