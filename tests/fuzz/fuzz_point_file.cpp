// The point-file parser (firmware/io/point_file.hpp) on arbitrary bytes, with
// the third column read both ways. Either a clear error (a reason and a line
// inside the file) or a result that keeps the reader's promises: finite
// coordinates within kMaxCoordinate, no consecutive duplicates inside a path,
// each path at least two distinct points, one source line per point, columns
// all-or-none.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.hpp"
#include "io/point_file.hpp"

namespace {

void check(const kerf::io::PointFile& f, std::string_view text) {
  using kerf::io::kMaxCoordinate;
  if (!f.ok) {
    FUZZ_CHECK(!f.reason.empty(), "an error without a reason");
    std::size_t lines = 1;
    for (char c : text) lines += c == '\n';
    FUZZ_CHECK(f.line <= lines + 1, "an error line past the end of the text");
    FUZZ_CHECK(!kerf::io::describe_error(f).empty(), "no error message");
    return;
  }
  const std::size_t n = f.points.size();
  FUZZ_CHECK(n >= 2, "a file accepted with fewer than two points");
  FUZZ_CHECK(f.point_lines.size() == n, "one source line per point");
  FUZZ_CHECK(f.tols.empty() || f.tols.size() == n, "tols on every point or none");
  FUZZ_CHECK(f.tangents.empty() || f.tangents.size() == n, "tangents on every point or none");
  FUZZ_CHECK(!f.path_begin.empty() && f.path_begin[0] == 0, "the first path starts at 0");
  for (std::size_t p = 0; p < f.path_begin.size(); ++p) {
    const std::size_t b = f.path_begin[p];
    const std::size_t e = p + 1 < f.path_begin.size() ? f.path_begin[p + 1] : n;
    FUZZ_CHECK(b < e && e <= n, "paths in order");
    FUZZ_CHECK(e - b >= 2, "a path with fewer than two points");
    for (std::size_t k = b + 1; k < e; ++k)
      FUZZ_CHECK(!(f.points[k].x == f.points[k - 1].x && f.points[k].y == f.points[k - 1].y),
                 "consecutive duplicate points kept");
  }
  for (std::size_t k = 0; k < n; ++k) {
    FUZZ_CHECK(std::isfinite(f.points[k].x) && std::isfinite(f.points[k].y), "a non-finite point");
    FUZZ_CHECK(std::abs(f.points[k].x) <= kMaxCoordinate && std::abs(f.points[k].y) <= kMaxCoordinate,
               "a coordinate beyond kMaxCoordinate");
    if (k > 0) FUZZ_CHECK(f.point_lines[k] > f.point_lines[k - 1], "point lines increase");
  }
  for (double t : f.tols) FUZZ_CHECK(std::isfinite(t) && t > 0, "a tol that is not positive");
  for (const auto& t : f.tangents)
    FUZZ_CHECK(std::isfinite(t.x) && std::isfinite(t.y) && std::abs(std::hypot(t.x, t.y) - 1) < 1e-9,
               "a tangent that is not a unit vector");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  for (bool angles : {false, true}) check(kerf::io::parse_points(text, "fuzz.txt", angles), text);
  return 0;
}
