// libgpiod 2.x (Debian 13): a request is its own object, made from settings
// and a line config; the chip only describes lines. One request per line keeps
// this layer the same shape as v1's. Written against the v2 documentation;
// this machine has libgpiod 1.6, so it is compiled only where 2.x is installed.
#include <gpiod.h>

#include <cerrno>

#include "gpiod_api.hpp"

namespace kerf::hal::gpiod_api {

struct Chip {
  gpiod_chip* chip;
};
struct Line {
  gpiod_line_request* request;
  unsigned offset;
};

const char* name() { return "libgpiod 2"; }

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
  gpiod_chip_info* ci = ::gpiod_chip_get_info(chip->chip);
  if (ci == nullptr) return false;
  info.name = ::gpiod_chip_info_get_name(ci);
  info.label = ::gpiod_chip_info_get_label(ci);
  info.num_lines = static_cast<int>(::gpiod_chip_info_get_num_lines(ci));
  ::gpiod_chip_info_free(ci);
  return true;
}

int chip_find_line(Chip* chip, const char* line_name) {
  return ::gpiod_chip_get_line_offset_from_name(chip->chip, line_name);
}

std::string line_consumer(Chip* chip, int offset) {
  gpiod_line_info* li = ::gpiod_chip_get_line_info(chip->chip, static_cast<unsigned>(offset));
  if (li == nullptr) return "";
  const char* who = ::gpiod_line_info_get_consumer(li);
  std::string consumer = who == nullptr ? "" : who;
  ::gpiod_line_info_free(li);
  return consumer;
}

namespace {

Line* request(Chip* chip, int offset, const char* consumer, bool output, bool initial_high) {
  const unsigned off = static_cast<unsigned>(offset);
  gpiod_line_settings* settings = ::gpiod_line_settings_new();
  gpiod_line_config* line_cfg = ::gpiod_line_config_new();
  gpiod_request_config* req_cfg = ::gpiod_request_config_new();
  gpiod_line_request* req = nullptr;
  if (settings != nullptr && line_cfg != nullptr && req_cfg != nullptr &&
      ::gpiod_line_settings_set_direction(settings, output ? GPIOD_LINE_DIRECTION_OUTPUT
                                                           : GPIOD_LINE_DIRECTION_INPUT) == 0 &&
      (!output || ::gpiod_line_settings_set_output_value(
                      settings, initial_high ? GPIOD_LINE_VALUE_ACTIVE
                                             : GPIOD_LINE_VALUE_INACTIVE) == 0) &&
      ::gpiod_line_config_add_line_settings(line_cfg, &off, 1, settings) == 0) {
    ::gpiod_request_config_set_consumer(req_cfg, consumer);
    req = ::gpiod_chip_request_lines(chip->chip, req_cfg, line_cfg);
  }
  // The frees below must not clobber the request's errno (busy, ...).
  const int err = errno;
  ::gpiod_request_config_free(req_cfg);
  ::gpiod_line_config_free(line_cfg);
  ::gpiod_line_settings_free(settings);
  errno = err;
  return req == nullptr ? nullptr : new Line{req, off};
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
  ::gpiod_line_request_release(line->request);
  delete line;
}

int line_get(Line* line) {
  const gpiod_line_value v = ::gpiod_line_request_get_value(line->request, line->offset);
  return v == GPIOD_LINE_VALUE_ERROR ? -1 : (v == GPIOD_LINE_VALUE_ACTIVE ? 1 : 0);
}

bool line_set(Line* line, bool high) {
  return ::gpiod_line_request_set_value(line->request, line->offset,
                                        high ? GPIOD_LINE_VALUE_ACTIVE
                                             : GPIOD_LINE_VALUE_INACTIVE) == 0;
}

}  // namespace kerf::hal::gpiod_api
