// The G-code reader (firmware/job/gcode_reader.hpp) on arbitrary bytes, then
// the interpreter (job/gcode_interp.hpp: offsets, G92, G53, modes, tools,
// program actions, user M-codes, parameters, expressions and O-word flow
// under a loop cap of 100000 blocks) with a configuration that maps a tool, user
// M-codes and the torch output, then the program built from it (`kerf
// sim`/`kerf run` on a G-code file). Either a clear error or a file whose
// blocks and polylines keep the reader's promises, an interpreter state that
// is sane (a selected system in range, finite offsets and positions, values
// in their ranges), and a program whose paths and actions are consistent.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_check.hpp"
#include "job/gcode_program.hpp"
#include "job/gcode_reader.hpp"
#include "../support/interp_settings.hpp"

namespace {

using namespace kerf::job;

bool finite3(const double* v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

void check_interpretation(const GcodeFile& g) {
  const InterpSettings settings = kerf_test::interp_case_settings();
  MachineState start;
  start.g5x[1][0] = 10;  // a non-zero offset to start from
  start.coord = 1;
  Interpretation it;
  std::string error;
  if (!interpret(g, settings, start, it, error)) {
    FUZZ_CHECK(!error.empty() && error.find(':') != std::string::npos, "a refused program without FILE:LINE");
    return;
  }
  const MachineState& st = it.state;
  FUZZ_CHECK(st.coord >= 0 && st.coord < kCoordSystems, "the selected coordinate system out of range");
  for (const auto& o : st.g5x) FUZZ_CHECK(finite3(o), "a non-finite work offset");
  FUZZ_CHECK(finite3(st.g92), "a non-finite G92 offset");
  std::size_t line = 0;
  bool flow = false;  // a loop or a call runs lines again: the canonical moves go back in the file
  for (const auto& [name, c] : it.constructs) flow = flow || name.rfind("O-word", 0) == 0;
  for (const Canon& c : it.canon) {
    FUZZ_CHECK(flow || c.line >= line, "canonical moves out of line order");
    line = c.line;
    FUZZ_CHECK(finite3(c.end) && std::isfinite(c.centre[0]) && std::isfinite(c.centre[1]), "a non-finite move");
    FUZZ_CHECK(c.feed_mm_min >= 0 || c.kind == CanonKind::traverse, "a negative feed");
    if (c.kind == CanonKind::dwell) FUZZ_CHECK(c.value >= 0, "a negative dwell");
    if (c.kind == CanonKind::feed_percent) FUZZ_CHECK(c.value >= 10 && c.value <= 100, "a feed % out of 10..100");
    if (c.kind == CanonKind::tolerance) FUZZ_CHECK(c.value > 0 && c.value <= settings.fit_tol, "a G64 tolerance over fit.tol");
    if (c.kind == CanonKind::wait_input) FUZZ_CHECK(c.mode >= 0 && c.mode <= 4, "an M66 mode out of 0..4");
    if (c.kind == CanonKind::torch) FUZZ_CHECK(c.index == 0 || c.index == 1, "a torch neither on nor off");
  }
  for (const auto& [name, c] : it.constructs)
    FUZZ_CHECK(c.count >= 1 && (c.handling == "run" || c.handling == "recorded" || c.handling == "ignored"),
               "a construct without a use or a handling");
  GcodeProgram prog;
  if (!build_program(g, settings, it, prog, error)) {
    FUZZ_CHECK(!error.empty(), "a program refused without a reason");
    return;
  }
  FUZZ_CHECK(prog.paths.size() == prog.points.path_begin.size() && !prog.paths.empty(), "paths and their points");
  FUZZ_CHECK(prog.point_feed.size() == prog.points.points.size(), "a feed for each point");
  for (const double f : prog.point_feed) FUZZ_CHECK(f >= 0 && std::isfinite(f), "a negative or non-finite feed");
  for (std::size_t k = 0; k < prog.paths.size(); ++k) {
    const std::size_t b = prog.points.path_begin[k];
    const std::size_t e = k + 1 < prog.paths.size() ? prog.points.path_begin[k + 1] : prog.points.points.size();
    FUZZ_CHECK(e >= b + 2, "a path of fewer than two points");
    FUZZ_CHECK(prog.paths[k].torch != prog.dry_run, "a torch path in a dry run, or a dry path in a cut");
  }
  std::size_t before = 0;
  for (const ProgramAction& a : prog.actions) {
    FUZZ_CHECK(a.before_path >= before && a.before_path <= prog.paths.size(), "actions out of order");
    before = a.before_path;
  }
  for (const auto& q : prog.points.points) FUZZ_CHECK(std::isfinite(q.x) && std::isfinite(q.y), "a non-finite point");
  // The same program on a machine with a z axis: every z move lands before or after a path.
  InterpSettings with_z = settings;
  with_z.z_axis = true;
  GcodeProgram zp;
  if (!build_program(g, with_z, it, zp, error)) return;
  std::size_t z_moves = 0;
  for (const ProgramPath& p : zp.paths)
    for (const std::vector<ProgramMove>* moves : {&p.before, &p.after})
      for (const ProgramMove& m : *moves) {
        FUZZ_CHECK(std::isfinite(m.xy.x) && std::isfinite(m.xy.y) && std::isfinite(m.z_end) && m.feed_mm_min >= 0,
                   "a z-axis move not finite, or with a negative feed");
        z_moves += m.z ? 1 : 0;
      }
  FUZZ_CHECK(z_moves == zp.z_moves, "a z move lost between the paths");
  FUZZ_CHECK(zp.paths.size() >= prog.paths.size(), "fewer paths with a z axis");
}

}  // namespace

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
      FUZZ_CHECK(!b.dynamic || (b.words.empty() && !b.xy_line), "a dynamic line with words or in a polyline");
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
  if (g.ok) check_interpretation(g);
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
