// Reading each section of the config file. First pass: every value on its
// own (type, range, unknown keys). The checks across values (check_*) run
// after it, only when the first pass found nothing, so that they never
// compare against a value that was refused.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "config/table_reader.hpp"

namespace kerf::config {

// One GPIO line as configured, for the duplicate check.
struct LineUse {
  std::string path;  // gpio.estop, gpio.limit[1]
  std::string chip;  // without /dev/
  int offset = -1;
  std::string name;
  std::uint32_t line = 0;  // of the offset, or of the name
  int number = -1;         // [[gpio.output]] / [[gpio.input]]: the program number
  bool output = false;
  std::uint32_t number_line = 0;
};

void read_machine(TableReader& r, Machine& m);
void read_link(TableReader& r, Link& link);
void read_gpio(TableReader& r, hal::GpioConfig& gpio, std::vector<LineUse>& uses);
void read_fit(TableReader& r, Fit& fit);
void read_cut(TableReader& r, Cut& cut);
void read_rt(TableReader& r, Rt& rt);
// The interpreter's sections (program_section.cpp): [tools], [materials], [mcodes], [outputs], [sim].
void read_program(TableReader& root, Program& p, Sim& sim);
void read_bench(TableReader& r, Bench& bench);

void check_machine(TableReader& machine, const Machine& m);
void check_link(TableReader& link_reader, const Link& link, const TableReader& machine,
                const Machine& m);
void check_gpio(const std::vector<LineUse>& uses, Problems& problems);
// A program output that is also [outputs] torch, mist or flood's number is
// fine for mist/flood (M7/M8 drive it) but not for the torch (gpio.torch is it).
void check_program_outputs(const std::vector<LineUse>& uses, const Program& p, Problems& problems);
void check_cut(TableReader& cut_reader, const Cut& cut, TableReader& machine, const Machine& m);

}  // namespace kerf::config
