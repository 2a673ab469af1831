// A token as an error message may show it: in double quotes, printable ASCII
// kept, the rest escaped (\xNN), cut short after 40 characters.
#pragma once

#include <string>
#include <string_view>

namespace kerf::io {

std::string quote(std::string_view s);

}  // namespace kerf::io
