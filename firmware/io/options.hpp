// Checking option values given as text, so that every message has the same
// "--option: reason" form (the caller prefixes "kerf: ").
#pragma once

#include <cstdint>
#include <string>

namespace kerf::io {

// Exit codes of the kerf command.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // the fit or the output failed
inline constexpr int kExitUsage = 2;    // bad options or bad input

std::string quoted(const std::string& s);

// Prints "kerf: message" on stderr; returns kExitUsage (2).
int usage_error(const std::string& message);

// A finite number > 0 (allow_zero: >= 0) for option `name`, with nothing
// around it; an empty value is "required".
bool parse_length(const std::string& name, const std::string& text, bool allow_zero, double& out,
                  std::string& error);

// --pieces: a whole number >= 1.
bool parse_pieces(const std::string& text, std::uint32_t& pieces, std::string& error);

}  // namespace kerf::io
