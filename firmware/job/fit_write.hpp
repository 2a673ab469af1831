// Writing a finished fit in the format `kerf fit --format` names: esgi,
// json, gcode or svg, to stdout or atomically to --output.
#pragma once

#include <string>
#include <vector>

#include "io/options.hpp"
#include "job/fit_options.hpp"
#include "io/fit_output.hpp"
#include "io/point_file.hpp"

namespace kerf::job {

// True for the names --format accepts.
bool known_fit_format(const std::string& format);

// Checks --feed and --output against --format; 0 when fine, else the usage
// error's exit code (the message printed). Sets feed (mm/min).
int check_output_options(const FitOptions& opts, double& feed);

struct FitToWrite {
  const io::FitReport* report = nullptr;  // pieces' first/last local to their path...
  const io::PointFile* in = nullptr;
  std::vector<std::uint32_t> piece_offset;  // ...plus this (the path's first point)
  double tol_left = 0.0;  // the band's (or the vertex tol's) half-widths, mm
  double tol_right = 0.0;
  double feed = 1000.0;
};

// "1 piece", "5 pieces".
std::string count(std::size_t n, const char* one, const char* many);

// The line `kerf fit` ends with, on stderr: "kerf: FILE: N points, [P paths, ]"
// then `what`, the fit's time, `note` (write_fit's) and the duplicates dropped.
void print_fit_summary(const io::PointFile& in, std::size_t paths, const std::string& what, double ms,
                       const std::string& note);

// Formats and writes it; kExitOk, or kExitFailure with a message printed.
// `note` gets what the summary line should add (gcode: decimals and the
// measured deviation after rounding).
int write_fit(const FitOptions& opts, const FitToWrite& w, std::string& note);

}  // namespace kerf::job
