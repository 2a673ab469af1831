// An independent referee of `kerf weld`: it reads the input and the output
// G-code with its own small parser (no code shared with firmware/io) and
// checks, against the input polylines:
//  - every line that is not an XY feed move (G1/G2/G3 with only N X Y I J F
//    words) is unchanged and in order (a "G1" inserted into a bare modal
//    line is allowed: a written arc replaced the modal G1 it relied on);
//  - the comments come out in the same order;
//  - between two unchanged lines, the output moves start where the input
//    moves start, end within tol of where they end, pass within tol of every
//    input vertex, and stay within tol of the input polyline at sample points
//    spaced tol/4 or closer (arcs as a controller draws them: from the start
//    around the I/J centre, widened by the start/end radius difference);
//  - no arc is written the long way round (that is the band check above).
// Absolute (G90) files only; a G91 file is checked line for line.
#pragma once

#include <string>

namespace kerf_test {

struct WeldCheck {
  bool ok = false;
  std::string why;          // the first failure, with the output line
  double max_deviation = 0; // measured, file units
  std::size_t input_moves = 0;
  std::size_t output_moves = 0;
};

WeldCheck check_weld(const std::string& input, const std::string& output, double tol);

}  // namespace kerf_test
