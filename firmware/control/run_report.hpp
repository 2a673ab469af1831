// What a run of a job reports, `kerf sim` and `kerf run` alike: the JSON
// report and the one-line summary, from the controller's report and the
// journal.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "control/controller.hpp"
#include "control/cut_rule_note.hpp"
#include "control/journal.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::control {

// A G-code construct the program used and how kerf handled it.
struct ConstructUse {
  std::string name;      // "G54", "M6", "G64 P", "M67 E3 (feed %)" ...
  std::string handling;  // run | recorded | ignored
  std::size_t count = 0, first_line = 0;
};

struct RunSummary {
  bool simulated = true;  // kerf sim; false for kerf run (no trace, no simulated time)
  std::string state;   // done | fault | estop
  std::string reason;  // empty when done
  std::string link;    // modbus-tcp | modbus-rtu
  std::size_t paths = 0, pierces = 0;
  std::size_t z_moves = 0;          // z axis: z moves sent (0 without one)
  double final_z = 0;               // mm, the board's z at the end
  std::size_t planned = 0;          // segments in the job
  std::size_t executed = 0;         // completed in this run
  std::uint64_t executed_total = 0; // completed over every run of the job (the journal's count)
  std::uint64_t duplicates = 0;     // segments completed more than once
  std::int64_t last_executed = 0;   // 1-based number of the last completed segment, 0 for none
  std::size_t resumed_from = 0;     // 1-based first segment of this run; 0: a new job
  std::uint32_t runs = 1;
  bool has_cut_to = false;          // where the torch went off inside the next segment
  CutPoint cut_to;
  bool torch_on = false;
  bool torch_off_valid = false;
  Vec2<double> torch_off_at{}, stopped_at{};
  std::uint64_t link_errors = 0;
  std::uint32_t board_duplicates = 0;  // resent segments the board dropped
  double max_path_deviation_mm = 0.0;
  double duration_s = 0.0;  // simulated
  double wall_s = 0.0;
  std::string rt;           // the cycle loop's statistics, when paced in real time
  std::string rt_histogram; // its wake-up lateness histogram, one bin per line
  // A G-code program's (control/program_job.hpp describe_program).
  bool gcode = false;
  bool dry_run = false;     // no torch word: run with the torch off
  bool dry_run_option = false;  // --dry-run: torch and gas outputs held off
  std::vector<ConstructUse> constructs;
  std::vector<std::string> notes;
  std::size_t dwells = 0, pauses = 0, actions = 0;  // program actions run
  // Safety (controller.hpp RunReport): resets of the E-stop latch accepted,
  // the last one refused (empty: none), and the following error: the largest
  // seen, and at a following-error fault the gap and its limit then.
  std::uint32_t resets = 0;
  std::string reset_refused;
  double max_ferror_mm = 0.0, ferror_at_fault_mm = 0.0, ferror_limit_mm = 0.0;
  // Where the cutting rules applied (FittedJob::cut_rules): path, rule, feed %.
  std::vector<CutRuleNote> cut_rules;
  // Where the fit's bounded window forced a commit (Job::forced_commits).
  std::size_t forced_commits = 0;
};

// The summary's fields that come from the controller's report and the
// journal (when there is one; otherwise from this run alone). `resumed`:
// this run started from a journal.
RunSummary summarise_run(const RunReport& r, std::size_t paths, const std::string& link, bool resumed,
                         const Journal* journal);

std::string format_run_json(const RunSummary& s);
std::string format_run_summary(const RunSummary& s);

}  // namespace kerf::control
