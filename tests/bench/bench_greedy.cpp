// Optimal against greedy on the same inputs: kerf's fewest-pieces search and
// ArcWelder's greedy rule ("extend the arc while every point fits, stop at the
// first failure"), both with kerf's exact pair test (tests/support/
// greedy_weld.hpp), so the comparison isolates the search. For every file of
// tests/data/gcode, on the G1 polylines `kerf weld` may replace (tol in the
// file's units, relative runs left out), per criterion and tol: the points, both move counts and their ratio. Prints
// what it counts; exits 1 if optimal ever exceeds greedy (it cannot).
//
// usage: kerf_bench_greedy [--criterion vertex|band|both] [FILE...]
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "greedy_weld.hpp"
#include "job/gcode_reader.hpp"

namespace {

struct Counts {
  std::size_t points = 0;
  std::size_t optimal = 0;
  std::size_t greedy = 0;
};

Counts count_file(const kerf::job::GcodeFile& g, double tol, kerf_test::WeldRule rule) {
  Counts c;
  for (const kerf::job::GPolyline& pl : g.polylines) {
    const std::vector<kerf::Vec2<double>> p = kerf_test::distinct_points(pl.points);
    if (p.size() < 2 || pl.relative) continue;  // as kerf weld: relative runs stay as they are
    const double t = tol / (pl.inches ? 25.4 : 1.0);
    c.points += p.size();
    c.optimal += kerf_test::optimal_pieces(p, t, rule);
    c.greedy += kerf_test::greedy_pieces(p, t, rule);
  }
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  bool vertex = true, band = true;
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--criterion") == 0 && k + 1 < argc) {
      const std::string c = argv[++k];
      vertex = c != "band";
      band = c != "vertex";
    } else {
      files.emplace_back(argv[k]);
    }
  }
  if (files.empty()) {
    for (const auto& e : std::filesystem::directory_iterator(KERF_GCODE_DIR))
      if (e.path().extension() != ".md") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
  }
  const double tols[] = {0.005, 0.01, 0.025, 0.05};
  std::printf("%-46s %-6s %6s %8s %8s %8s %6s\n", "file", "rule", "tol", "points", "optimal", "greedy", "ratio");
  bool sound = true;
  for (const kerf_test::WeldRule rule : {kerf_test::WeldRule::vertex, kerf_test::WeldRule::band}) {
    if ((rule == kerf_test::WeldRule::vertex && !vertex) || (rule == kerf_test::WeldRule::band && !band)) continue;
    const char* name = rule == kerf_test::WeldRule::vertex ? "vertex" : "band";
    for (const double tol : tols) {
      Counts all;
      for (const std::string& f : files) {
        const kerf::job::GcodeFile g = kerf::job::read_gcode(f);
        if (!g.ok) {
          std::fprintf(stderr, "%s:%zu: %s\n", f.c_str(), g.line, g.reason.c_str());
          return 2;
        }
        const Counts c = count_file(g, tol, rule);
        if (c.points == 0) continue;
        all.points += c.points;
        all.optimal += c.optimal;
        all.greedy += c.greedy;
        sound = sound && c.optimal <= c.greedy;
        std::printf("%-46s %-6s %6.3f %8zu %8zu %8zu %6.3f\n",
                    std::filesystem::path(f).filename().string().c_str(), name, tol, c.points, c.optimal,
                    c.greedy, static_cast<double>(c.optimal) / static_cast<double>(c.greedy));
      }
      std::printf("%-46s %-6s %6.3f %8zu %8zu %8zu %6.3f\n", "ALL", name, tol, all.points, all.optimal, all.greedy,
                  static_cast<double>(all.optimal) / static_cast<double>(all.greedy));
    }
  }
  if (!sound) std::printf("optimal above greedy somewhere: a search or pair test bug\n");
  return sound ? 0 : 1;
}
