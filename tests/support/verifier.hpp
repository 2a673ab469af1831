// An independent check of a fit's output, for the tests. It shares no code
// with core/ (kerf_test_support does not even see core's include folder): its
// own point and piece types, plain std C++, plain geometry.
//
// verify() accepts a list of pieces for points p_0..p_{n-1} at tolerance tol
// when all of this holds:
//   - the pieces run contiguously from index 0 to n-1, each with first < last;
//   - each piece starts on p_first and ends on p_last (1e-9 relative);
//   - an arc's end points are equally far from its centre (1e-9 relative),
//     its direction is +1 (counter-clockwise) or -1 (clockwise); a line's is 0;
//   - every inner point p_k, first < k < last, is within tol of the full
//     circle (arc) or of the infinite line (line), to tol (1 + 1e-9) plus
//     1e-12 of the input's scale;
//   - the arc runs through its inner points: the inner point farthest from the
//     chord, if more than tol from it, lies (about the centre) inside the sweep
//     from start to end in direction E, with tol / radius of angular slack;
//   - with Reach::arc, every inner point is within tol of the arc (segment).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace kerf_test {

struct VPoint {
  double x = 0;
  double y = 0;
};

struct VPiece {
  bool arc = false;
  std::size_t first = 0;
  std::size_t last = 0;
  double sx = 0, sy = 0;  // start
  double ex = 0, ey = 0;  // end
  double cx = 0, cy = 0;  // centre (arcs only)
  int dir = 0;            // E: +1 CCW, -1 CW, 0 for a line
};

// The line piece from pts[first] to pts[last]; an arc starts from it too.
VPiece line_piece(const std::vector<VPoint>& pts, std::size_t first, std::size_t last);

struct VerifyReport {
  bool ok = true;
  std::string why;  // the first problem found, empty when ok
};

// How far an inner point may be: from the piece's full circle (or infinite
// line), the ESGI rules' measure, or from the arc (or segment) itself, the
// optimal vertex fit's: inside the arc's sweep the distance to the circle,
// outside it the distance to the nearer end.
enum class Reach { circle, arc };

VerifyReport verify(const std::vector<VPoint>& pts, const std::vector<VPiece>& pieces, double tol,
                    Reach reach = Reach::circle);

// The distance of p to the piece's arc (or segment).
double arc_distance(const VPoint& p, const VPiece& piece);

// The largest distance of the piece's inner points to its arc (or segment).
double piece_error(const std::vector<VPoint>& pts, const VPiece& piece);

// The length of the diagonal of the points' bounding box.
double scale_of(const std::vector<VPoint>& pts);

}  // namespace kerf_test
