// The thermal-cutting rules of the configuration's [cut] table: slower small
// holes and tight arcs, an overcut past a hole's start, and the torch-height
// lock (velocity anti-dive). A struct of its own, so that a tool or material
// table can carry these fields per material later.
//
// Defaults follow QtPlasmaC's hole mode: holes below 32 mm at 60 % of the cut
// feed; its velocity anti-dive locks the torch height below 90 % of the feed.
#pragma once

namespace kerf::config {

struct CutRules {
  double hole_diameter = 32;  // mm, >= 0: closed paths smaller than this are holes (0: none)
  double hole_feed = 60;      // % of the cut feed for holes, (0, 100]
  double arc_radius = 0;      // mm, >= 0: arcs (outside holes) below this radius (0: none)
  double arc_feed = 100;      // % of the cut feed for those arcs, (0, 100]
  double overcut = 0;         // mm, >= 0: cut on past a hole's start, then the torch goes off
  double vad = 90;            // %, [0, 100]: thc_lock while the speed is below this of the feed
};

class TableReader;

// Reads the keys above from the [cut] table (before its finish()).
void read_cut_rules(TableReader& r, CutRules& rules);

}  // namespace kerf::config
