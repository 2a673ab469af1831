// A program built against an installed kerf (find_package or pkg-config):
// fits points on a circle of radius 10 and prints the fit. It exits 0 only
// when the fit is the one arc it must be, so a broken install cannot pass by
// merely compiling.
#include <cmath>
#include <cstdio>
#include <vector>

#include <io/fit_output.hpp>
#include <io/fit_storage.hpp>
#include <kerf/fit/fit.hpp>

int main() {
  std::vector<kerf::Vec2<double>> pts;
  for (int i = 0; i <= 12; ++i) {
    const double t = 0.2 * i;
    pts.push_back({10.0 * std::cos(t), 10.0 * std::sin(t)});
  }
  kerf::io::FitStorage storage(pts.size());
  const auto r = kerf::fit::fit_min_count<double>({pts.data(), pts.size()}, 0.001,
                                                  kerf::fit::Method::optimal,
                                                  storage.workspace(), storage.pieces());
  if (!r.ok()) return 1;
  kerf::io::FitReport report;
  report.fit = r.value();
  report.pieces = {storage.pieces().data(), r.value().pieces};
  std::fputs(kerf::io::format_esgi(report).c_str(), stdout);
  const kerf::Segment<double>& s = storage.piece(0).segment;
  const bool one_arc = r.value().pieces == 1 && s.is_arc() && std::fabs(s.radius() - 10.0) < 1e-6;
  return one_arc ? 0 : 1;
}
