// `kerf weld` on the G-code corpus (tests/data/gcode): per file, the reader's
// and the welder's lines per second and the output/input move ratio at
// tol 0.025 mm, with the ArcWelder ratios issue 10 quotes for comparison.
// Prints figures measured in this run; it asserts nothing about speed.
//
// usage: kerf_bench_weld [--criterion band|vertex|both] [--tol MM] [--no-split] [FILE...]
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/weld.hpp"
#include "io/gcode_reader.hpp"

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// ArcWelder at 0.025 mm, travel arcs allowed (issue 10); 0 when not quoted.
double arcwelder_ratio(const std::string& path) {
  if (path.find("jsdc-laser") != std::string::npos) return 0.037;
  if (path.find("tball-engrave") != std::string::npos) return 0.025;
  if (path.find("tball-pocket") != std::string::npos) return 0.069;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  double tol = 0.025;
  std::vector<std::string> criteria{"band", "vertex"};
  bool split = true;
  std::vector<std::string> files;
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--tol") == 0 && k + 1 < argc) tol = std::atof(argv[++k]);
    else if (std::strcmp(argv[k], "--criterion") == 0 && k + 1 < argc) {
      const std::string c = argv[++k];
      criteria = c == "both" ? std::vector<std::string>{"band", "vertex"} : std::vector<std::string>{c};
    } else if (std::strcmp(argv[k], "--no-split") == 0) split = false;
    else files.emplace_back(argv[k]);
  }
  if (files.empty())
    for (const char* f : {"cncjs_jsdc-laser.gcode", "cncjs_tball-engrave.gcode", "cncjs_tball-pocket.gcode",
                          "cncjs_Circle_Diamond_Square_Calibration.gcode", "cncjs_sample_slic3r.gcode",
                          "cncjs_octocat.gcode"})
      files.push_back(std::string(KERF_GCODE_DIR) + "/" + f);
  std::printf("tol %.4g mm, split at sharp turns: %s\n", tol, split ? "yes" : "no");
  std::printf("%-46s %-7s %8s %8s %7s %9s %12s %12s\n", "file", "crit", "in", "out", "ratio",
              "arcwelder", "read lines/s", "weld lines/s");
  for (const std::string& path : files) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    auto t0 = std::chrono::steady_clock::now();
    const kerf::io::GcodeFile g = kerf::io::parse_gcode(text, path);
    const double read_s = seconds_since(t0);
    if (!g.ok) {
      std::fprintf(stderr, "%s\n", kerf::io::describe_error(g).c_str());
      return 1;
    }
    for (const std::string& c : criteria) {
      kerf::cli::WeldOptions o;
      o.tol_mm = tol;
      o.criterion = c;
      o.split_turns = split;
      std::string out, error;
      kerf::cli::WeldStats st;
      t0 = std::chrono::steady_clock::now();
      if (!kerf::cli::weld_gcode(g, o, out, st, error)) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 1;
      }
      const double weld_s = seconds_since(t0) + read_s;
      const double lines = static_cast<double>(g.blocks.size());
      const std::string name = path.substr(path.find_last_of('/') + 1);
      std::printf("%-46s %-7s %8zu %8zu %6.2f%% %8.1f%% %12.0f %12.0f\n", name.c_str(), c.c_str(),
                  st.input_moves, st.output_moves,
                  100.0 * static_cast<double>(st.output_moves) / static_cast<double>(st.input_moves),
                  100.0 * arcwelder_ratio(path), lines / read_s, lines / weld_s);
      std::fflush(stdout);
    }
  }
  return 0;
}
