// Writing a command's output so that a failure never leaves half a file.
#pragma once

#include <string>

namespace kerf::io {

// Writes all of `text` to `path`: "-" is stdout; a regular file (or a new
// one) is written to PATH.tmp and renamed over it; anything else (/dev/null,
// a fifo) is written in place, never replaced. False with errno set on
// failure, and then no partial file is left.
bool write_output(const std::string& path, const std::string& text);

}  // namespace kerf::io
