#include "simulated/sim_output.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace kerf::simulated {

double sample_deviation(Vec2<double> pos, const Segment<double>* const near[3]) {
  // The sample is the drives' position; the segment number is the
  // setpoint's. Drives that lag their setpoints (CAN: a SYNC or two) are
  // still on the previous piece just after a joint, so a sample counts
  // against the nearest of its piece and the pieces either side.
  double d = distance_to_segment(*near[1], pos);
  if (near[0] != nullptr) d = std::min(d, distance_to_segment(*near[0], pos));
  if (near[2] != nullptr) d = std::min(d, distance_to_segment(*near[2], pos));
  return d;
}

const char* csv_header(bool with_z) {
  return with_z ? "t_s,x_mm,y_mm,segment,torch,thc_lock,z_mm\n" : "t_s,x_mm,y_mm,segment,torch,thc_lock\n";
}

int format_trace_row(const sim::TraceSample& s, bool with_z, char* out, std::size_t size) {
  // std::to_chars with a precision writes what printf's %.6f writes, much faster.
  char* p = out;
  char* const end = out + size - 1;
  auto fixed6 = [&](double v, char sep) {
    p = std::to_chars(p, end, v, std::chars_format::fixed, 6).ptr;
    if (p < end) *p++ = sep;
  };
  auto whole = [&](unsigned v, char sep) {
    p = std::to_chars(p, end, v).ptr;
    if (p < end) *p++ = sep;
  };
  fixed6(s.t_s, ',');
  fixed6(s.pos.x, ',');
  fixed6(s.pos.y, ',');
  whole(s.seq, ',');
  whole(s.torch ? 1U : 0U, ',');
  whole(s.thc_lock ? 1U : 0U, with_z ? ',' : '\n');
  if (with_z) fixed6(s.z, '\n');
  *p = '\0';
  return static_cast<int>(p - out);
}

}  // namespace kerf::simulated
