// The one check every command makes on a file it reads, before anything else
// reads it: a missing file, a directory or a file that cannot be read is
// refused as "FILE: reason" with exit 2 (io::kExitUsage), not met later as an
// internal error (a directory once reached the G-code reader's size probe).
#pragma once

#include <string>

namespace kerf::io {

// Why `path` cannot be read as an input, or "" when it can: "cannot open:
// No such file or directory", "is a directory", "cannot read: Input/output
// error". "-" (stdin) passes. A regular file must give its first byte (a
// positioned read, so nothing is consumed); a pipe or a device is not even
// opened (a named pipe's writer would start into a pipe this check closes):
// its reader reports.
std::string input_problem(const std::string& path);

// Prints "FILE: reason" on stderr and returns false when `path` cannot be
// read; an empty path (an option not given) passes.
bool input_readable(const std::string& path);

}  // namespace kerf::io
