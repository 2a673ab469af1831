// `kerf fit`'s options as given: shared by the command (app/fit_command.cpp)
// and the parts of the fit that read them (job/fit_stream.cpp, job/fit_write.cpp).
#pragma once

#include <string>

namespace kerf::job {

// The options as given, still text: fit_command checks them itself so that
// every message has the same "kerf: --option: ..." form.
struct FitOptions {
  std::string tol;
  std::string pieces;
  std::string tol_left;   // band only
  std::string tol_right;  // band only
  std::string criterion = "vertex";
  std::string method = "optimal";
  std::string format = "esgi";  // esgi, json, gcode or svg
  std::string feed;             // gcode: F in mm/min (default 1000)
  std::string output = "-";     // -o: a file (written atomically) or - for stdout
  std::string tangents;                  // biarc: given | estimate (default: given when
                                         // the file has them)
  std::string tangent_format = "vector";  // biarc: vector (x y tx ty) | angle (x y deg)
  std::string numeric = "double";  // double or fixed (kerf::Fixed), every criterion
  std::string tie_break;  // smallest (whole-input default) | none (--stream's only)
  bool stream = false;   // --stream: read and write piece by piece (job/fit_stream.cpp)
  std::string window;    // --stream: the points held at most
  std::string extent;    // --stream: the largest |x| or |y| (mm); needed for --numeric fixed
  std::string file;
};

}  // namespace kerf::job
