// A stand-in for one libgpiod version behind hal/gpio/src/gpiod_api.hpp, so
// that the backend's own logic (requests, torch safety, active-low,
// debounce, error paths, cleanup) runs against chips a test describes.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace kerf::fake_gpiod {

struct FakeLine {
  std::string name;
  std::string consumer;  // non-empty: busy, held by someone else
  bool level = false;    // the physical level (inputs: what the pin reads)
  bool fail_io = false;  // get/set fail with EIO
};

struct FakeChip {
  std::string name;
  std::string label;
  std::vector<FakeLine> lines;
};

struct World {
  std::map<std::string, FakeChip> chips;  // by path
  int open_chips = 0;
  int requested_lines = 0;
  // Every physical level written to an output, with its path and offset, in order.
  struct Write {
    std::string chip;
    int offset;
    bool high;
    bool initial;  // the value given with the request
  };
  std::vector<Write> writes;
};

// The one world the fake seam serves; tests reset it.
World& world();

}  // namespace kerf::fake_gpiod
