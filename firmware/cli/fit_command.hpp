// `kerf fit`: fit the fewest arcs to the points of a file, or the smallest
// tolerance for a number of pieces, and print them.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace kerf::cli {

// Exit codes of the kerf command.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // the fit or the output failed
inline constexpr int kExitUsage = 2;    // bad options or bad input

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
  std::string numeric = "double";  // vertex and band criteria: double or fixed (kerf::Fixed)
  std::string tie_break;  // smallest (whole-input default) | none (--stream's only)
  bool stream = false;   // --stream: read and write piece by piece (cli/fit_stream.cpp)
  std::string window;    // --stream: the points held at most
  std::string extent;    // --stream: the largest |x| or |y| (mm); needed for --numeric fixed
  std::string file;
};

// `kerf fit --stream --window N` (cli/fit_stream.cpp).
int run_fit_stream(const FitOptions& opts);

// `kerf fit --criterion biarc` (cli/fit_biarc_command.cpp).
int run_fit_biarc(const FitOptions& opts);

// Adds the `fit` subcommand to app, storing into opts.
CLI::App* add_fit_command(CLI::App& app, FitOptions& opts);

// Runs it; returns the exit code. Output goes to stdout only on success.
int run_fit(const FitOptions& opts);

}  // namespace kerf::cli
