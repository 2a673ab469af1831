// The G-code reader (firmware/job/gcode_reader.hpp) on arbitrary bytes, then
// the job built from it (`kerf sim`/`kerf run` on a G-code file). Either a
// clear error or a file whose blocks and polylines keep the reader's
// promises, and a job whose points keep the point file's.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_check.hpp"
#include "job/gcode_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const kerf::job::GcodeFile g = kerf::job::parse_gcode(text, "fuzz.nc");
  if (!g.ok) {
    FUZZ_CHECK(!g.reason.empty() && g.line >= 1, "an error without a reason or a line");
  } else {
    std::size_t line = 0;
    for (const kerf::job::GBlock& b : g.blocks) {
      FUZZ_CHECK(b.line > line, "blocks in line order");
      line = b.line;
      for (const kerf::job::GWord& w : b.words) {
        FUZZ_CHECK(w.pos + w.len <= b.text.size(), "a word outside its line");
        FUZZ_CHECK(std::isfinite(w.value), "a word with a non-finite value");
      }
    }
    for (const kerf::job::GPolyline& p : g.polylines) {
      FUZZ_CHECK(p.first_block <= p.last_block && p.last_block < g.blocks.size(), "polyline blocks");
      FUZZ_CHECK(p.points.size() >= 2 && p.point_block.size() == p.points.size(), "polyline points");
      for (const auto& q : p.points)
        FUZZ_CHECK(std::isfinite(q.x) && std::isfinite(q.y), "a non-finite polyline point");
    }
  }
  kerf::io::PointFile job;
  std::string error;
  if (kerf::job::gcode_job_from(g, job, error)) {
    FUZZ_CHECK(job.points.size() >= 2 && job.point_lines.size() == job.points.size(), "job points");
    for (const auto& q : job.points)
      FUZZ_CHECK(std::isfinite(q.x) && std::isfinite(q.y), "a non-finite job point");
  } else {
    FUZZ_CHECK(!error.empty(), "a refused job without a reason");
  }
  return 0;
}
