// hal::Gpio on the Linux GPIO character device through libgpiod (v1.6 or
// v2, chosen when CMake configures; see hal/README.md). Lines are found by
// chip and offset or by name; active-low and debouncing are done here in
// kerf, identically for both libgpiod versions. Everything is allocated in
// open_gpiod; read() and set_torch() allocate nothing.
#pragma once

#include <memory>
#include <string>

#include "kerf/hal/gpio.hpp"

namespace kerf::hal {

// Opens the chips and requests every used line of `cfg` (the torch as an
// output, logically off from the first instant). Null with the reason in
// `error` ("gpio: <role>: ...") on failure; nothing stays requested then.
// The returned object turns the torch off before it releases the lines.
std::unique_ptr<Gpio> open_gpiod(const GpioConfig& cfg, std::string& error);

// "libgpiod 1.6" or "libgpiod 2": the API this build was compiled against.
const char* gpiod_api_name();

}  // namespace kerf::hal
