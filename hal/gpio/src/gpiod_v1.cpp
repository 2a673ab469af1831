// libgpiod 1.6 (Debian 12, Ubuntu 24.04): lines are objects owned by the
// chip, requested one by one; closing the chip releases them.
#include <gpiod.h>

#include <cerrno>

#include "gpiod_api.hpp"

namespace kerf::hal::gpiod_api {

struct Chip {
  gpiod_chip* chip;
};
struct Line {
  gpiod_line* line;
};

const char* name() { return "libgpiod 1.6"; }

std::vector<std::string> chip_paths() { return gpio_lines::list_chip_paths("/dev"); }

Chip* chip_open(const char* path) {
  gpiod_chip* c = ::gpiod_chip_open(path);
  return c == nullptr ? nullptr : new Chip{c};
}

void chip_close(Chip* chip) {
  if (chip == nullptr) return;
  ::gpiod_chip_close(chip->chip);
  delete chip;
}

bool chip_info(Chip* chip, gpio_lines::ChipInfo& info) {
  info.name = ::gpiod_chip_name(chip->chip);
  info.label = ::gpiod_chip_label(chip->chip);
  info.num_lines = static_cast<int>(::gpiod_chip_num_lines(chip->chip));
  return true;
}

int chip_find_line(Chip* chip, const char* line_name) {
  gpiod_line* line = ::gpiod_chip_find_line(chip->chip, line_name);
  if (line == nullptr) return -1;
  return static_cast<int>(::gpiod_line_offset(line));
}

std::string line_consumer(Chip* chip, int offset) {
  gpiod_line* line = ::gpiod_chip_get_line(chip->chip, static_cast<unsigned>(offset));
  if (line == nullptr || ::gpiod_line_update(line) != 0) return "";
  const char* who = ::gpiod_line_consumer(line);
  return who == nullptr ? "" : who;
}

namespace {

Line* request(Chip* chip, int offset, const char* consumer, bool output, bool initial_high) {
  gpiod_line* line = ::gpiod_chip_get_line(chip->chip, static_cast<unsigned>(offset));
  if (line == nullptr) return nullptr;
  const int rc = output ? ::gpiod_line_request_output(line, consumer, initial_high ? 1 : 0)
                        : ::gpiod_line_request_input(line, consumer);
  return rc == 0 ? new Line{line} : nullptr;
}

}  // namespace

Line* line_request_input(Chip* chip, int offset, const char* consumer) {
  return request(chip, offset, consumer, false, false);
}

Line* line_request_output(Chip* chip, int offset, const char* consumer, bool initial_high) {
  return request(chip, offset, consumer, true, initial_high);
}

void line_release(Line* line) {
  if (line == nullptr) return;
  ::gpiod_line_release(line->line);
  delete line;
}

int line_get(Line* line) { return ::gpiod_line_get_value(line->line); }

bool line_set(Line* line, bool high) { return ::gpiod_line_set_value(line->line, high ? 1 : 0) == 0; }

}  // namespace kerf::hal::gpiod_api
