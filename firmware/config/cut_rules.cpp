#include "config/cut_rules.hpp"

#include "config/table_reader.hpp"

namespace kerf::config {

void read_cut_rules(TableReader& r, CutRules& rules) {
  r.non_negative("hole_diameter", rules.hole_diameter);
  r.positive_at_most("hole_feed", rules.hole_feed, 100);
  r.non_negative("arc_radius", rules.arc_radius);
  r.positive_at_most("arc_feed", rules.arc_feed, 100);
  r.non_negative("overcut", rules.overcut);
  r.number_in("vad", rules.vad, 0, 100);
}

}  // namespace kerf::config
