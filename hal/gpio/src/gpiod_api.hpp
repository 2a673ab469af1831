// The seam between kerf's GPIO backend and one libgpiod version. Exactly one
// of gpiod_v1.cpp and gpiod_v2.cpp is compiled (CMake picks it from the
// installed libgpiod's version), so everything above this seam is written
// once. Functions that fail return null / -1 / false with errno set.
#pragma once

#include <string>
#include <vector>

#include "kerf/hal/gpio/gpio_lines.hpp"

namespace kerf::hal::gpiod_api {

struct Chip;  // an open GPIO chip
struct Line;  // one requested line

const char* name();

// The chips there are, as device paths (gpio_lines::list_chip_paths for /dev).
std::vector<std::string> chip_paths();
Chip* chip_open(const char* path);
void chip_close(Chip* chip);
// Name, label and line count (path is the caller's).
bool chip_info(Chip* chip, gpio_lines::ChipInfo& info);
// The offset of the first line called `name`; -1 with errno ENOENT when there is none.
int chip_find_line(Chip* chip, const char* name);
// Who holds the line, when the kernel says; empty otherwise.
std::string line_consumer(Chip* chip, int offset);

// Physical levels: active-low is applied by kerf, never by the library.
Line* line_request_input(Chip* chip, int offset, const char* consumer);
Line* line_request_output(Chip* chip, int offset, const char* consumer, bool initial_high);
void line_release(Line* line);
int line_get(Line* line);  // 0 or 1, -1 on error
bool line_set(Line* line, bool high);

}  // namespace kerf::hal::gpiod_api
