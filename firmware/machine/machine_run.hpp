// `kerf run`'s cycle on the real machine, once the job is fitted and the
// devices and the journal are open (app/run_command.cpp; kerf-sim's bench
// run passes its simulated lines): the controller (machine_factory.hpp)
// in a periodic loop on absolute deadlines (SCHED_FIFO and mlockall where
// permitted), a status line a second on stderr, SIGINT or SIGTERM stopping
// it safely (torch off, motion stopped on the path, progress journaled),
// then the report (`report`: JSON, if named) and the summary on stdout. On a
// bench ([bench] enabled) every status line, the summary and the report say
// BENCH.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "control/cut_rule_note.hpp"
#include "control/job.hpp"
#include "control/job_source.hpp"
#include "control/run_report.hpp"
#include "control/journal.hpp"
#include "job/gcode_program.hpp"
#include "kerf/hal/gpio.hpp"
#include "kerf/hal/segment_link.hpp"

namespace kerf::machine {

// The `homed` of a run whose state file says homed (kerf home): the board's
// own homed flags are checked against it before anything moves.
inline constexpr const char* kHomedByKerfHome = "kerf home";

// Returns the exit code: 0 done, 1 stopped (fault, E-stop, signal) or the
// report could not be written. The E-stop latch starts latched: it opens on
// `reset_at_start` or the gpio.reset line (the caller refuses a run with
// neither). With a reset line, a stopped run waits latched for a reset and
// then finishes the job.
int run_on_machine(const control::Job& job, const config::Config& cfg, hal::SegmentLink& link, hal::Gpio& gpio,
                   control::Journal* journal, const control::ResumePoint& from, bool resumed, const std::string& report,
                   bool reset_at_start = false,
                   const job::GcodeProgram* program = nullptr,
                   const std::vector<control::CutRuleNote>* cut_rules = nullptr,  // for the report
                   bool dry_run = false,   // --dry-run: the report and the summary say so
                   const char* homed = nullptr);  // the report's "homed": how the position is known

// What the report says of the job beyond the controller's report (paths,
// segments planned, the program's facts, the cutting rules, forced
// commits), asked once the run has ended: a streamed job knows them only then.
using JobFacts = std::function<void(control::RunSummary&)>;

// The same run over a job source (kerf run's streamed job, control/streamed_job.hpp).
int run_on_machine(control::JobSource& job, const JobFacts& facts, const config::Config& cfg, hal::SegmentLink& link,
                   hal::Gpio& gpio, control::Journal* journal, const control::ResumePoint& from, bool resumed,
                   const std::string& report, bool reset_at_start, bool dry_run, const char* homed);

}  // namespace kerf::machine
