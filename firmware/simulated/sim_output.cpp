#include "simulated/sim_output.hpp"

#include <algorithm>
#include <cstdio>

namespace kerf::simulated {

double max_path_deviation(const std::vector<sim::TraceSample>& trace,
                          const std::vector<fit::Piece<double>>& pieces) {
  // The sample is the drives' position; the segment number is the
  // setpoint's. Drives that lag their setpoints (CAN: a SYNC or two) are
  // still on the previous piece just after a joint, so a sample counts
  // against the nearest of its piece and the pieces either side.
  double worst = 0.0;
  for (const sim::TraceSample& s : trace) {
    if (s.seq == 0 || s.seq > pieces.size()) continue;
    const std::size_t k = s.seq - 1;
    double d = distance_to_segment(pieces[k].segment, s.pos);
    if (k > 0) d = std::min(d, distance_to_segment(pieces[k - 1].segment, s.pos));
    if (k + 1 < pieces.size()) d = std::min(d, distance_to_segment(pieces[k + 1].segment, s.pos));
    if (d > worst) worst = d;
  }
  return worst;
}

std::string format_trace_csv(const std::vector<sim::TraceSample>& trace, bool with_z) {
  std::string out = with_z ? "t_s,x_mm,y_mm,segment,torch,thc_lock,z_mm\n" : "t_s,x_mm,y_mm,segment,torch,thc_lock\n";
  char line[192];
  for (const sim::TraceSample& s : trace) {
    std::snprintf(line, sizeof line, "%.6f,%.6f,%.6f,%u,%d,%d", s.t_s, s.pos.x, s.pos.y,
                  static_cast<unsigned>(s.seq), s.torch ? 1 : 0,
                  s.thc_lock ? 1 : 0);
    out += line;
    if (with_z) {
      std::snprintf(line, sizeof line, ",%.6f", s.z);
      out += line;
    }
    out += '\n';
  }
  return out;
}

}  // namespace kerf::simulated
