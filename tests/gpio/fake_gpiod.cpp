#include "fake_gpiod.hpp"

#include <cerrno>

#include "gpiod_api.hpp"

namespace kerf::fake_gpiod {
World& world() {
  static World w;
  return w;
}
}  // namespace kerf::fake_gpiod

namespace kerf::hal::gpiod_api {

using fake_gpiod::world;

struct Chip {
  std::string path;
};
struct Line {
  std::string path;
  int offset;
};

namespace {
fake_gpiod::FakeLine& line_of(const std::string& path, int offset) {
  return world().chips.at(path).lines.at(static_cast<std::size_t>(offset));
}
}  // namespace

const char* name() { return "fake"; }

std::vector<std::string> chip_paths() {
  std::vector<std::string> paths;
  for (const auto& [path, chip] : world().chips) paths.push_back(path);
  return paths;
}

Chip* chip_open(const char* path) {
  if (world().chips.count(path) == 0) {
    errno = ENOENT;
    return nullptr;
  }
  ++world().open_chips;
  return new Chip{path};
}

void chip_close(Chip* chip) {
  if (chip == nullptr) return;
  --world().open_chips;
  delete chip;
}

bool chip_info(Chip* chip, gpio_lines::ChipInfo& info) {
  const fake_gpiod::FakeChip& c = world().chips.at(chip->path);
  info.name = c.name;
  info.label = c.label;
  info.num_lines = static_cast<int>(c.lines.size());
  return true;
}

int chip_find_line(Chip* chip, const char* line_name) {
  const fake_gpiod::FakeChip& c = world().chips.at(chip->path);
  for (std::size_t i = 0; i < c.lines.size(); ++i)
    if (c.lines[i].name == line_name) return static_cast<int>(i);
  errno = ENOENT;
  return -1;
}

std::string line_consumer(Chip* chip, int offset) { return line_of(chip->path, offset).consumer; }

Line* line_request_input(Chip* chip, int offset, const char* consumer) {
  fake_gpiod::FakeLine& l = line_of(chip->path, offset);
  if (!l.consumer.empty()) {
    errno = EBUSY;
    return nullptr;
  }
  l.consumer = consumer;
  ++world().requested_lines;
  return new Line{chip->path, offset};
}

Line* line_request_output(Chip* chip, int offset, const char* consumer, bool initial_high) {
  Line* line = line_request_input(chip, offset, consumer);
  if (line == nullptr) return nullptr;
  line_of(chip->path, offset).level = initial_high;
  world().writes.push_back({chip->path, offset, initial_high, true});
  return line;
}

void line_release(Line* line) {
  if (line == nullptr) return;
  line_of(line->path, line->offset).consumer.clear();
  --world().requested_lines;
  delete line;
}

int line_get(Line* line) {
  const fake_gpiod::FakeLine& l = line_of(line->path, line->offset);
  if (l.fail_io) {
    errno = EIO;
    return -1;
  }
  return l.level ? 1 : 0;
}

bool line_set(Line* line, bool high) {
  fake_gpiod::FakeLine& l = line_of(line->path, line->offset);
  if (l.fail_io) {
    errno = EIO;
    return false;
  }
  l.level = high;
  world().writes.push_back({line->path, line->offset, high, false});
  return true;
}

}  // namespace kerf::hal::gpiod_api
