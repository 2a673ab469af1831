// The thermal-cutting rules (config/cut_rules.hpp) applied to a fitted job,
// where its segments are built: holes (closed paths smaller than
// hole_diameter) at hole_feed %, arcs below arc_radius at arc_feed %, and an
// overcut past each hole's start (the torch goes off at its end, as at the
// end of any path). Each application is noted, for the run's summary.
#pragma once

#include <string>
#include <vector>

#include "config/cut_rules.hpp"
#include "control/cut_rule_note.hpp"
#include "control/fit_paths.hpp"

namespace kerf::control {

// The largest extent (bounding box side) of a path, arcs' bulges included, mm.
double path_size(const CutPath& path);
// Whether the path ends where it started.
bool is_closed(const CutPath& path);

// Applies the rules to every path of `fitted` (feeds, overcut segments and
// their pieces) and returns what it did.
std::vector<CutRuleNote> apply_cut_rules(FittedJob& fitted, const config::CutRules& rules);

// One line per note: "path 2: hole 20 mm < 32 mm: 60 % feed".
std::string describe(const CutRuleNote& n, const config::CutRules& rules);
// Prints "kerf: FILE: " and the line, for each note, on stderr.
void say_cut_rules(const std::string& file, const std::vector<CutRuleNote>& notes,
                   const config::CutRules& rules);

}  // namespace kerf::control
