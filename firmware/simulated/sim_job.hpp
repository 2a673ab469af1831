// The job `kerf sim` runs, as its consumers take it: the JobSource the
// controller reads, the start, and what the report, the trace and the plot
// need, each asked for when it is needed and never as the whole fitted job
// (issue 24). load_sim_job() reads a point file, a G-code program or the
// built-in demo.
#pragma once

#include <memory>
#include <string>

#include "config/config.hpp"
#include "control/job_source.hpp"
#include "control/run_report.hpp"
#include "job/criterion.hpp"
#include "kerf/geom/segment.hpp"
#include "simulated/sim_plot.hpp"

namespace kerf::simulated {

struct SimJobSettings {
  job::Criterion criterion = job::Criterion::band;
  job::Numeric numeric = job::Numeric::floating;
  double tol = 0.025;      // mm
  double feed = 0;         // mm/min, the cut feed
  bool dry_run = false;    // --dry-run: torch and gas outputs held off
  bool whole = false;      // read and fit the file whole first (SimOptions::whole_job)
};

class SimJob {
 public:
  virtual ~SimJob() = default;
  virtual control::JobSource& source() = 0;
  // Where the axes power up: the first pierce point of a point job, the
  // configured start (sim.start) of a program.
  virtual Vec2<double> start() const = 0;
  // The first path's pierce point (a new run starts there).
  virtual Vec2<double> first_pierce() const = 0;
  // Job segment k's fitted piece, when still known (a streamed job: recent ones).
  virtual bool piece(std::size_t k, Segment<double>& out) = 0;
  // The input points for the plot, within its budget.
  virtual void plot_points(PlotKeeper& plot) = 0;
  // After the run: the job's part of the summary (cut rules, forced
  // commits, the program's constructs and notes).
  virtual void describe(control::RunSummary& sum) const = 0;
  // After the run: the program's notes on stderr ("kerf: sim: ..."), when
  // they were not known before it (a stream knows them at its end).
  virtual void say_notes() const {}
  virtual const std::string& file() const = 0;
};

// The job of `file` (empty: the demo), streamed unless s.whole. Prints "kerf: ..." and returns the
// exit code (2 bad input, 1 otherwise) on failure; 0 with `out` set.
int load_sim_job(const std::string& file, const config::Config& cfg, const SimJobSettings& s,
                 std::unique_ptr<SimJob>& out);

// The run's journal, by the job's id: none (empty path), a new one, or with
// `resume` the one a previous run left, and where this run starts: the
// first pierce point, or on resume where the journal says (its segment
// located in the source). "kerf: --journal: reason" and false on failure.
bool open_sim_journal(const std::string& path, bool resume, control::JobSource& source, Vec2<double> first_pierce,
                      std::unique_ptr<control::Journal>& out, control::ResumePoint& from);

}  // namespace kerf::simulated
