#include "simulated/sim_output.hpp"

#include <algorithm>
#include <cstdio>

namespace kerf::simulated {

double sample_deviation(const sim::TraceSample& s, const std::vector<fit::Piece<double>>& pieces) {
  // The sample is the drives' position; the segment number is the
  // setpoint's. Drives that lag their setpoints (CAN: a SYNC or two) are
  // still on the previous piece just after a joint, so a sample counts
  // against the nearest of its piece and the pieces either side.
  const std::size_t k = s.seq - 1;
  double d = distance_to_segment(pieces[k].segment, s.pos);
  if (k > 0) d = std::min(d, distance_to_segment(pieces[k - 1].segment, s.pos));
  if (k + 1 < pieces.size()) d = std::min(d, distance_to_segment(pieces[k + 1].segment, s.pos));
  return d;
}

const char* csv_header(bool with_z) {
  return with_z ? "t_s,x_mm,y_mm,segment,torch,thc_lock,z_mm\n" : "t_s,x_mm,y_mm,segment,torch,thc_lock\n";
}

int format_trace_row(const sim::TraceSample& s, bool with_z, char* out, std::size_t size) {
  const int n = with_z ? std::snprintf(out, size, "%.6f,%.6f,%.6f,%u,%d,%d,%.6f\n", s.t_s, s.pos.x, s.pos.y,
                                       static_cast<unsigned>(s.seq), s.torch ? 1 : 0, s.thc_lock ? 1 : 0, s.z)
                       : std::snprintf(out, size, "%.6f,%.6f,%.6f,%u,%d,%d\n", s.t_s, s.pos.x, s.pos.y,
                                       static_cast<unsigned>(s.seq), s.torch ? 1 : 0, s.thc_lock ? 1 : 0);
  return std::min(n, static_cast<int>(size) - 1);
}

}  // namespace kerf::simulated
