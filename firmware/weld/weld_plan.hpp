// kerf weld's planning (weld/weld.hpp): a polyline prepared (its points
// without jitter, cut into parts at sharp turns), and the plan of one part
// from where the machine is at its start. Planning reads its inputs only:
// parts are planned on several threads (weld/weld.cpp) and written in order.
#pragma once

#include <cstddef>
#include <exception>
#include <string>
#include <vector>

#include "weld/weld.hpp"
#include "job/gcode_reader.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::weld::detail {

using P = Vec2<double>;

// A piece as written: its rounded end and centre, the text after the G word.
struct Written {
  std::string text;
  P end{};
  double deviation = 0;
};

// A planned piece: written as `written`, or kept as its input lines.
struct Planned {
  fit::Piece<double> piece;
  bool keep = false;  // write its input lines
  Written written;
};

// A polyline made ready to plan: its distinct points, the run fitted (the
// points without their jitter) and where that run is cut into parts.
struct Run {
  bool welded = false;  // false: its lines are passed through (G91, a single point)
  double unit = 1, tol = 0, fit_tol = 0, moved = 0;
  std::vector<P> pts;                   // distinct consecutive points
  std::vector<std::size_t> from_index;  // each one's index in the polyline
  std::vector<P> simple;                // pts without the jitter
  std::vector<std::size_t> kept_index;  // each one's index in pts
  std::vector<std::size_t> cuts;        // the parts: simple[cuts[j]..cuts[j + 1]]

  std::size_t parts() const { return cuts.empty() ? 0 : cuts.size() - 1; }
  P part_start(std::size_t j) const { return simple[cuts[j]]; }
};

// Prepares pl; the parts are cut at turns sharper than 90 degrees (opts.split_turns).
void prepare(const job::GPolyline& pl, const WeldOptions& opts, int decimals, Run& r);

// What planning one part gives: planned apart from the output, as the parts
// are planned on several threads and written in file order.
struct PartPlan {
  bool ok = true;
  std::string error;  // when !ok
  P from_in{};        // where the machine was at its start when it was planned
  P from_out{};       // where the machine is after it
  std::vector<Planned> pieces;
  std::size_t kept = 0;          // pieces kept as their input lines (rounding)
  std::exception_ptr exception;  // thrown while planning on a worker thread
};

// Plans part j of r with the machine at `from` at its start (see Planner in
// weld/weld_plan.cpp); out.ok false with out.error when a fit fails.
void plan_part(const Run& r, std::size_t j, P from, const WeldOptions& opts, int decimals, PartPlan& out);

}  // namespace kerf::weld::detail
