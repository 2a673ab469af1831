// A job as `kerf run` and `kerf check` read it: a point file or a G-code
// program (interpreted with the machine state's offsets), fitted into a
// controller job with the configuration's fit and cutting rules.
#pragma once

#include <string>

#include "config/config.hpp"
#include "control/fit_paths.hpp"
#include "control/streamed_job.hpp"
#include "io/point_file.hpp"
#include "job/gcode_program.hpp"

namespace kerf::app {

struct JobInput {
  bool gcode = false;
  io::PointFile points;     // a point file
  job::GcodeProgram prog;   // a G-code program (its points are prog.points)
  control::FittedJob fitted;
  // Where the job's points and their lines come from.
  const io::PointFile& source() const { return gcode ? prog.points : points; }
};

// Reads and fits `path`. strict: kerf run's interpreter settings and
// machine (control::machine_can_run). On failure prints why ("FILE:LINE:
// reason") and returns the exit code; 0 on success. With `cannot_run`, a
// program the machine cannot run is not a failure: the reason goes there.
int read_and_fit(const config::Config& cfg, const std::string& path, bool strict, const char* who, JobInput& out,
                 std::string* cannot_run = nullptr);

// kerf run's job, streamed from `path` (control/streamed_job.hpp) with the
// configuration's fit, feeds, cutting rules, soft limits and machine (each
// action as machine_can_run checks it); a bench or `dry_run` holds the torch
// off, `dry_run` the outputs too. Opens it and waits, before anything moves,
// for a full ring or the file's end; then prints the program's notes if it
// has ended. On failure prints why ("FILE:LINE: reason") and returns the
// exit code; 0 on success.
int open_streamed(const config::Config& cfg, const std::string& path, bool dry_run, const char* who,
                  control::StreamedJob& out);

}  // namespace kerf::app
