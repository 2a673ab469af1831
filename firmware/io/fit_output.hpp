// Writing a fit as text: the ESGI'104 report's arc list, or JSON.
// Both build the whole text in memory; the caller writes it out only when
// everything succeeded, so a failure never leaves half an output behind.
#pragma once

#include <string>

#include "kerf/core/span.hpp"
#include "kerf/fit/fit.hpp"

namespace kerf::io {

// Every number is printed with this many significant digits (coordinates
// with more where needed: coordinate_digits): enough to
// rebuild the path, few enough to be the same on every target. (At 12, the
// last digits of errors and centres differed between x86-64 and aarch64,
// where GCC contracts a * b + c into fused multiply-adds.)
inline constexpr int kDigits = 10;

struct FitReport {
  const char* criterion = "vertex";
  const char* method = "optimal";  // as spelled on the command line
  fit::Fit<double> fit{};
  Span<const fit::Piece<double>> pieces{};  // fit.pieces of them
  double zero_below = 0.0;  // numbers smaller than this print as 0: see resolution()
  int digits = kDigits;     // significant digits of coordinates: see coordinate_digits()
  // Biarcs: pieces 2k and 2k+1 are biarc k's two arcs (fit.pieces counts the
  // arcs, biarcs = fit.pieces / 2).
  bool biarcs = false;
};

// The size below which a number computed from these points is rounding noise
// (1e-12 of the largest coordinate): a centre at 3e-17 instead of 0, say,
// whose digits would differ from one target to another.
double resolution(Span<const Vec2<double>> pts);

// The significant digits that print every coordinate of the pieces (ends and
// centres) to within tol / 1000: kDigits, or more (up to 17, all a double
// has) far from the origin or for a tiny tol, where kDigits would move a
// printed arc by more than the tol (at 1e9 mm, ten digits are 0.1 mm).
int coordinate_digits(Span<const fit::Piece<double>> pieces, double tol);

// "# ..." comment lines, "Number of arcs is Narc = N", then one line per piece:
//   A (x1,y1) (x2,y2) (xc,yc) E     an arc, E = 1 counter-clockwise, -1 clockwise
//   L (x1,y1) (x2,y2)               a line
// Biarcs: "# Number of biarcs is K", and "# biarc k: points i..j" before each
// biarc's two lines (the first ends where the second starts: the joint).
std::string format_esgi(const FitReport& r);

// One piece's esgi line, newline included (format_esgi's, and what
// `kerf fit --stream` writes as each piece is decided).
std::string esgi_piece_line(const Segment<double>& s, double zero_below, int digits);

// {"criterion", "method", "tol", "max_error", "pieces": [{"type", "first",
// "last", "start", "end", "centre" and "dir" (arcs only), "error"}]}; with
// biarcs also "biarcs": K and per piece "biarc": k (0-based) and "part": 1|2.
std::string format_json(const FitReport& r);

// One number as both formats print it: kDigits significant digits ("%.10g"),
// or `digits`,
// 0 for anything smaller in magnitude than zero_below, never "-0".
std::string format_number(double v, double zero_below = 0.0, int digits = kDigits);

}  // namespace kerf::io
