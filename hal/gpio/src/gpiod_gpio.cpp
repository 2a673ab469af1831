// The libgpiod backend, written once over the version seam (gpiod_api.hpp):
// chip lookup, line resolution, requests, active-low, debounce, errors.
#include "kerf/hal/gpio/gpiod_gpio.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "gpiod_api.hpp"
#include "kerf/hal/debouncer.hpp"
#include "kerf/hal/gpio/gpio_lines.hpp"

namespace kerf::hal {

namespace {

namespace api = gpiod_api;
using gpio_lines::ChipInfo;
using gpio_lines::LineAddress;
using gpio_lines::LineRole;

struct OpenChip {
  ChipInfo info;
  api::Chip* chip = nullptr;
};

struct Input {
  std::string role;
  std::string chip;
  int offset = -1;
  api::Line* line = nullptr;
  Debouncer debounce;
  int slot = 0;  // which GpioInputs field: see field(); -1: a program input
  int number = -1;
};

// A program output (M62..M65 P number).
struct Output {
  int number = -1;
  std::string chip;
  int offset = -1;
  api::Line* line = nullptr;
  bool active_low = false;
};

class GpiodGpio final : public Gpio {
 public:
  explicit GpiodGpio(const GpioConfig& cfg) : cfg_(cfg) {}
  ~GpiodGpio() override {
    // Torch off before anything is released: a released output keeps its
    // level on most chips, and the torch must never be left burning.
    if (torch_ != nullptr) api::line_set(torch_, torch_active_low_);
    outputs_off();
    for (Input& in : inputs_) api::line_release(in.line);
    for (Input& in : program_inputs_) api::line_release(in.line);
    for (Output& o : outputs_) api::line_release(o.line);
    api::line_release(torch_);
    api::line_release(watchdog_);
    api::line_release(thc_lock_);
    for (OpenChip& c : chips_) api::chip_close(c.chip);
  }
  GpiodGpio(const GpiodGpio&) = delete;
  GpiodGpio& operator=(const GpiodGpio&) = delete;

  bool open(std::string& error);

  bool read(double now_s, GpioInputs& in) override {
    in = GpioInputs{};
    in.limit_count = static_cast<std::uint8_t>(cfg_.limits.size());
    for (Input& line : inputs_) {
      const int level = api::line_get(line.line);
      if (level < 0) {
        const int err = errno;
        std::snprintf(error_, sizeof error_, "gpio: %s: reading line %d on %s failed: %s",
                      line.role.c_str(), line.offset, line.chip.c_str(), std::strerror(err));
        return false;
      }
      field(in, line.slot) = line.debounce.update(level != 0, now_s);
    }
    return true;
  }

  bool set_torch(bool on) override {
    if (torch_ == nullptr) return true;  // no torch line configured: nothing to drive
    if (api::line_set(torch_, on != torch_active_low_)) return true;
    const int err = errno;
    std::snprintf(error_, sizeof error_, "gpio: torch: setting line %d on %s failed: %s",
                  torch_offset_, torch_chip_.c_str(), std::strerror(err));
    return false;
  }

  bool set_watchdog(bool level) override {
    if (watchdog_ == nullptr || api::line_set(watchdog_, level != watchdog_active_low_)) return true;
    std::snprintf(error_, sizeof error_, "gpio: watchdog: setting its line failed: %s", std::strerror(errno));
    return false;
  }

  bool set_thc_lock(bool on) override {
    if (thc_lock_ == nullptr || api::line_set(thc_lock_, on != thc_lock_active_low_)) return true;
    std::snprintf(error_, sizeof error_, "gpio: thc_lock: setting its line failed: %s", std::strerror(errno));
    return false;
  }

  bool set_output(int number, bool on) override {
    for (Output& o : outputs_) {
      if (o.number != number) continue;
      if (api::line_set(o.line, on != o.active_low)) return true;
      const int err = errno;
      std::snprintf(error_, sizeof error_, "gpio: output %d: setting line %d on %s failed: %s", number, o.offset,
                    o.chip.c_str(), std::strerror(err));
      return false;
    }
    std::snprintf(error_, sizeof error_, "gpio: output %d: no such line ([[gpio.output]] number = %d)", number,
                  number);
    return false;
  }

  bool outputs_off() override {
    bool ok = true;
    for (Output& o : outputs_) ok = set_output(o.number, false) && ok;  // every one, even after a failure
    return ok;
  }

  bool read_input(int number, double now_s, bool& value) override {
    for (Input& in : program_inputs_) {
      if (in.number != number) continue;
      const int level = api::line_get(in.line);
      if (level < 0) {
        const int err = errno;
        std::snprintf(error_, sizeof error_, "gpio: %s: reading line %d on %s failed: %s", in.role.c_str(),
                      in.offset, in.chip.c_str(), std::strerror(err));
        return false;
      }
      value = in.debounce.update(level != 0, now_s);
      return true;
    }
    std::snprintf(error_, sizeof error_, "gpio: input %d: no such line ([[gpio.input]] number = %d)", number,
                  number);
    return false;
  }

  const char* last_error() const override { return error_; }

 private:
  // Slots: 0 arc_ok, 1 estop, 2 hold, 3 cycle_start, 4 reset, 5 + i limit i.
  static bool& field(GpioInputs& in, int slot) {
    switch (slot) {
      case 0: return in.arc_ok;
      case 1: return in.estop;
      case 2: return in.hold;
      case 3: return in.cycle_start;
      case 4: return in.reset;
      default: return in.limit[static_cast<std::size_t>(slot - 5)];
    }
  }
  static int slot_of(const LineRole& r) {
    if (r.limit_index >= 0) return 5 + r.limit_index;
    if (r.role == "reset") return 4;
    if (r.role == "arc_ok") return 0;
    if (r.role == "estop") return 1;
    if (r.role == "hold") return 2;
    return 3;
  }

  // Opens (once) the chip a spec names. Labels are matched by opening every chip.
  OpenChip* chip_for(const std::string& role, const std::string& spec, std::string& error);
  OpenChip* open_path(const std::string& role, const std::string& path, std::string& error);
  bool resolve(const LineRole& r, OpenChip*& chip, int& offset, std::string& error);
  bool request(const LineRole& r, OpenChip& chip, int offset, std::string& error);

  GpioConfig cfg_;
  std::vector<OpenChip> chips_;
  std::vector<Input> inputs_;
  std::vector<Input> program_inputs_;
  std::vector<Output> outputs_;
  api::Line* torch_ = nullptr;
  api::Line* watchdog_ = nullptr;
  api::Line* thc_lock_ = nullptr;
  bool thc_lock_active_low_ = false;
  bool torch_active_low_ = false, watchdog_active_low_ = false;
  int torch_offset_ = -1;
  std::string torch_chip_;
  char error_[200] = {};
};

OpenChip* GpiodGpio::open_path(const std::string& role, const std::string& path,
                               std::string& error) {
  for (OpenChip& c : chips_)
    if (c.info.path == path) return &c;
  api::Chip* chip = api::chip_open(path.c_str());
  if (chip == nullptr) {
    const int err = errno;
    if (err == ENOENT) error = gpio_lines::no_such_chip(role, path);
    else if (err == ENOTTY || err == ENODEV || err == EINVAL) error = gpio_lines::not_a_chip(role, path);
    else error = gpio_lines::cannot_open(role, path, err);
    return nullptr;
  }
  chips_.push_back(OpenChip{ChipInfo{path, "", "", 0}, chip});
  if (!api::chip_info(chip, chips_.back().info)) {
    error = gpio_lines::cannot_open(role, path, errno);
    return nullptr;  // stays in chips_: the destructor closes it
  }
  return &chips_.back();
}

OpenChip* GpiodGpio::chip_for(const std::string& role, const std::string& spec,
                              std::string& error) {
  const std::string path = gpio_lines::chip_path_for(spec);
  if (!path.empty()) {
    OpenChip* c = open_path(role, path, error);
    // "gpiochip7" missing: name it as configured, not as the path kerf made of it.
    if (c == nullptr && error == gpio_lines::no_such_chip(role, path))
      error = gpio_lines::no_such_chip(role, spec);
    return c;
  }
  for (const std::string& p : api::chip_paths()) {
    OpenChip* c = open_path(role, p, error);
    if (c == nullptr) return nullptr;
    if (c->info.label == spec) return c;
  }
  error = gpio_lines::no_such_chip(role, spec);
  return nullptr;
}

bool GpiodGpio::resolve(const LineRole& r, OpenChip*& chip, int& offset, std::string& error) {
  const GpioLineConfig& line = *r.cfg;
  if (line.offset >= 0) {
    if (line.chip.empty()) {
      error = "gpio: " + r.role + ": an offset needs a chip";
      return false;
    }
    chip = chip_for(r.role, line.chip, error);
    if (chip == nullptr) return false;
    offset = line.offset;
    return gpio_lines::check_offset(r.role, chip->info, offset, error);
  }
  std::vector<std::size_t> searched;  // indexes into chips_: pointers move as it grows
  if (!line.chip.empty()) {
    OpenChip* c = chip_for(r.role, line.chip, error);
    if (c == nullptr) return false;
    searched.push_back(static_cast<std::size_t>(c - chips_.data()));
  } else {
    for (const std::string& p : api::chip_paths()) {
      OpenChip* c = open_path(r.role, p, error);
      if (c == nullptr) return false;
      searched.push_back(static_cast<std::size_t>(c - chips_.data()));
    }
  }
  chip = nullptr;
  for (std::size_t i : searched) {
    const int found = api::chip_find_line(chips_[i].chip, line.name.c_str());
    if (found < 0) continue;
    if (chip != nullptr) {
      error = gpio_lines::name_ambiguous(r.role, line.name, chip->info.name, chips_[i].info.name);
      return false;
    }
    chip = &chips_[i];
    offset = found;
  }
  if (chip != nullptr) return true;
  std::vector<ChipInfo> infos;
  for (std::size_t i : searched) infos.push_back(chips_[i].info);
  error = gpio_lines::name_not_found(r.role, line.name, infos, !line.chip.empty());
  return false;
}

bool GpiodGpio::request(const LineRole& r, OpenChip& chip, int offset, std::string& error) {
  const char* consumer = cfg_.consumer.c_str();
  // The torch starts logically off: physically high when it is active-low.
  api::Line* line = r.output
                        ? api::line_request_output(chip.chip, offset, consumer, r.cfg->active_low)
                        : api::line_request_input(chip.chip, offset, consumer);
  if (line == nullptr) {
    const int err = errno;
    error = err == EBUSY ? gpio_lines::busy(r.role, chip.info.name, offset,
                                            api::line_consumer(chip.chip, offset))
                         : gpio_lines::request_failed(r.role, chip.info.name, offset, err);
    return false;
  }
  if (r.number >= 0) {  // a program line: outputs start logically off, as the torch does
    if (r.output) outputs_.push_back(Output{r.number, chip.info.name, offset, line, r.cfg->active_low});
    else
      program_inputs_.push_back(Input{r.role, chip.info.name, offset, line,
                                      Debouncer(r.cfg->debounce_s, r.cfg->active_low), -1, r.number});
    return true;
  }
  if (r.output && r.role == "thc_lock") {
    thc_lock_ = line;
    thc_lock_active_low_ = r.cfg->active_low;
    return true;
  }
  if (r.output && r.role == "watchdog") {
    watchdog_ = line;
    watchdog_active_low_ = r.cfg->active_low;
    return true;
  }
  if (r.output) {
    torch_ = line;
    torch_active_low_ = r.cfg->active_low;
    torch_offset_ = offset;
    torch_chip_ = chip.info.name;
    return true;
  }
  inputs_.push_back(Input{r.role, chip.info.name, offset, line,
                          Debouncer(r.cfg->debounce_s, r.cfg->active_low), slot_of(r), -1});
  return true;
}

bool GpiodGpio::open(std::string& error) {
  std::vector<LineRole> roles;
  if (!gpio_lines::list_lines(cfg_, roles, error)) return false;
  // Resolve everything before requesting anything, so that a config mistake
  // never leaves a line requested, even for a moment.
  std::vector<LineAddress> where;
  std::vector<std::size_t> chip_of;
  std::vector<int> offsets;
  for (const LineRole& r : roles) {
    OpenChip* chip = nullptr;
    int offset = -1;
    if (!resolve(r, chip, offset, error)) return false;
    where.push_back(LineAddress{chip->info.name, offset});
    chip_of.push_back(static_cast<std::size_t>(chip - chips_.data()));
    offsets.push_back(offset);
  }
  if (!gpio_lines::check_distinct(roles, where, error)) return false;
  inputs_.reserve(roles.size());
  program_inputs_.reserve(roles.size());
  outputs_.reserve(roles.size());
  for (std::size_t i = 0; i < roles.size(); ++i)
    if (!request(roles[i], chips_[chip_of[i]], offsets[i], error)) return false;
  return true;
}

}  // namespace

std::unique_ptr<Gpio> open_gpiod(const GpioConfig& cfg, std::string& error) {
  // The lines point into the copy of cfg the backend owns.
  auto gpio = std::make_unique<GpiodGpio>(cfg);
  if (!gpio->open(error)) return nullptr;  // the destructor releases what was opened
  return gpio;
}

const char* gpiod_api_name() { return gpiod_api::name(); }

}  // namespace kerf::hal
