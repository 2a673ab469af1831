// Where a thermal-cutting rule applied (control/cut_rules.hpp): kept with
// the fitted job for the run report.
#pragma once

#include <cstddef>
#include <string>

namespace kerf::control {

struct CutRuleNote {
  std::size_t path = 0;     // 0-based
  std::string rule;         // "hole", "arc" or "overcut"
  std::size_t segment = 0;  // 0-based within the path (hole: 0, overcut: its first)
  double value = 0;         // hole: its size (mm); arc: its radius (mm); overcut: length (mm)
  double feed_percent = 100;
};

}  // namespace kerf::control
