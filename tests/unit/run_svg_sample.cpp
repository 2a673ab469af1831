// Writes two run plots for the XML check in tests/unit/CMakeLists.txt:
// argv[1] a full one (two paths, arcs, a trace with rapids), argv[2] one with
// no trace at all.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/run_svg.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

bool write(const char* path, const std::string& text) {
  std::FILE* f = std::fopen(path, "wb");
  if (f == nullptr) return false;
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  return std::fclose(f) == 0 && ok;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: run_svg_sample FULL.svg EMPTY.svg\n");
    return 2;
  }
  using V = kerf::Vec2<double>;
  using Seg = kerf::Segment<double>;
  kerf::io::RunPlot plot;
  plot.title = "sample <run> & \"plot\" \u00b1 bad byte \xff, control \x01";
  plot.tol = 0.2;
  std::vector<V> circle;
  for (int i = 0; i <= 36; ++i)
    circle.push_back(V{20 + 6 * std::cos(i * 0.1745329), 20 + 6 * std::sin(i * 0.1745329)});
  plot.paths = {circle, {V{0, 0}, V{40, 0}, V{40, 30}}};
  plot.pieces = {Seg::arc(V{26, 20}, V{26, 20}, V{20, 20}, 1), Seg::line(V{0, 0}, V{40, 0}),
                 Seg::arc(V{40, 0}, V{40, 30}, V{40, 15}, -1)};
  plot.piece_path = {0, 1, 1};
  double t = 0;
  auto go = [&](V p, bool torch) { plot.trace.push_back({t += 0.01, p, 1, torch}); };
  for (int i = 0; i < 20; ++i) go(V{26.0 * i / 20, 20.0 * i / 20}, false);
  for (int i = 0; i <= 360; ++i) go(V{20 + 6 * std::cos(i * kPi / 180), 20 + 6 * std::sin(i * kPi / 180)}, true);
  for (int i = 0; i <= 20; ++i) go(V{26 - 26.0 * i / 20, 20 - 20.0 * i / 20}, false);
  for (int i = 0; i <= 400; ++i) go(V{0.1 * i, 0}, true);
  bool ok = write(argv[1], kerf::io::format_run_svg(plot));
  plot.trace.clear();
  plot.pieces.clear();
  plot.paths.clear();
  ok = write(argv[2], kerf::io::format_run_svg(plot)) && ok;
  if (!ok) std::perror("run_svg_sample");
  return ok ? 0 : 1;
}
