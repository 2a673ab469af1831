// The first pass over a point file for a streamed run (control/ring_job_source.hpp):
// before anything moves, the file is read and fitted once to its end (the
// same producer, control/job_stream.hpp) and every segment counted; a bad
// line is refused here, FILE:LINE, with nothing started. The journal's id is
// FNV-1a over the file's bytes and the fit's settings (the fit is
// deterministic: the same bytes and settings are the same segments), so a
// resume refuses another file or other settings. Memory: the producer's
// window and ring, whatever the file's length.
#pragma once

#include <string>

#include "control/job_stream.hpp"
#include "control/ring_job_source.hpp"

namespace kerf::control {

// False with "FILE:LINE: reason" (or "FILE: reason").
bool first_pass(const std::string& file, const JobStreamSetup& setup, JobSummary& out, std::string& error);

}  // namespace kerf::control
