// Every path of every G-code file in tests/data, fitted at several
// tolerances as `kerf sim` and `kerf run` fit it (control::fit_paths), sent
// through the Modbus slot encoding (hal/modbus register_map) and handed to
// the board's acceptance (motion::prepare_segment, what the interpolator
// checks when a segment is queued), each segment starting where the board's
// previous one ended: no segment may be refused.
//
// The paths come from kerf's reader (job::read_gcode_job). A file it refuses
// only for starting with a cut (jscut's tball files) is read with `G0 X0 Y0`
// put in front; a file it refuses otherwise is read by the independent reader
// (tests/support/toolpath_reader.hpp) and its cut moves sampled into paths,
// so that every file's geometry goes through the fit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "control/fit_paths.hpp"
#include "job/gcode_reader.hpp"
#include "kerf/hal/modbus/register_map.hpp"
#include "kerf/motion/path_geometry.hpp"
#include "toolpath_reader.hpp"

namespace kerf {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> gcode_files() {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(KERF_TEST_DATA_DIR))
    if (e.is_regular_file() && job::is_gcode_path(e.path().string())) out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

// The independent reader's cut moves as point paths: arcs sampled with a
// chord error below 0.001 mm, a new path wherever a cut does not start where
// the previous one ended, and where Z moves (as the interpreter splits a path
// where Z changes with the torch on, on a machine with no Z axis).
io::PointFile sampled_paths(const kerf_test::Toolpath& t) {
  io::PointFile pf;
  pf.ok = true;
  const double kPi = 3.14159265358979323846;
  auto add = [&](Vec2<double> p, std::size_t line) {
    if (pf.points.size() > pf.path_begin.back() && pf.points.back() == p) return;  // no duplicates
    pf.points.push_back(p);
    pf.point_lines.push_back(line);
  };
  auto drop_lone_point = [&] {
    if (!pf.path_begin.empty() && pf.points.size() - pf.path_begin.back() < 2) {
      pf.points.resize(pf.path_begin.back());
      pf.point_lines.resize(pf.path_begin.back());
      pf.path_begin.pop_back();
    }
  };
  Vec2<double> last{NAN, NAN};
  bool split_after = false;
  for (const kerf_test::TMove& m : kerf_test::cut_moves(t)) {
    const Vec2<double> s{m.start.x, m.start.y};
    if (!(s == last) || m.after_z || m.z_moves || split_after) {
      drop_lone_point();
      pf.path_begin.push_back(pf.points.size());
      add(s, m.line);
    }
    if (m.arc) {
      const double r = std::hypot(m.start.x - m.centre.x, m.start.y - m.centre.y);
      const double a0 = std::atan2(m.start.y - m.centre.y, m.start.x - m.centre.x);
      const double a1 = std::atan2(m.end.y - m.centre.y, m.end.x - m.centre.x);
      double sweep = m.dir > 0 ? a1 - a0 : a0 - a1;
      while (sweep <= 1e-12) sweep += 2 * kPi;
      const double step = r > 0.001 ? 2 * std::acos(1 - 0.001 / r) : sweep;
      const int n = std::max(1, static_cast<int>(std::ceil(sweep / step)));
      for (int k = 1; k < n; ++k) {
        const double a = a0 + m.dir * sweep * k / n;
        add({m.centre.x + r * std::cos(a), m.centre.y + r * std::sin(a)}, m.line);
      }
    }
    add({m.end.x, m.end.y}, m.line);
    last = {m.end.x, m.end.y};
    split_after = m.z_moves;
  }
  drop_lone_point();
  return pf;
}

// The paths of a file, and how they were read.
io::PointFile read_paths(const std::string& file, std::string& how) {
  io::PointFile in;
  std::string error;
  if (job::read_gcode_job(file, in, error)) return how = "kerf's reader", in;
  if (error.find("unknown position") != std::string::npos) {
    const std::string tmp = ::testing::TempDir() + "kerf_contract_" + fs::path(file).filename().string();
    {
      std::ofstream o(tmp, std::ios::binary);
      std::ifstream i(file, std::ios::binary);
      o << "G0 X0 Y0\n" << i.rdbuf();
    }
    if (job::read_gcode_job(tmp, in, error)) return how = "kerf's reader, G0 X0 Y0 in front", in;
  }
  const kerf_test::Toolpath t = kerf_test::read_toolpath(file);
  if (!t.ok) {
    how = "refused by both readers: " + error + " / " + t.error;
    return io::PointFile{};
  }
  const std::size_t at = error.find(fs::path(file).filename().string());
  how = "the independent reader; kerf's: " + (at == std::string::npos ? error : error.substr(at));
  return sampled_paths(t);
}

// One Modbus slot written and read back, as the board receives it.
hal::SegmentCommand over_modbus(const hal::SegmentCommand& c) {
  std::uint16_t slot[hal::modbus_map::kSlotRegs] = {};
  hal::SegmentCommand s = c;
  s.seq = 1;
  EXPECT_TRUE(hal::modbus_map::encode_slot(s, slot));
  hal::SegmentCommand d;
  const char* why = "";
  EXPECT_TRUE(hal::modbus_map::decode_slot(slot, d, why)) << why;
  return d;
}

Vec2<double> position_over_modbus(Vec2<double> p) {
  hal::SegmentCommand c;
  c.end = p;
  c.feed = 1;
  return over_modbus(c).end;
}

// refused.tsv: files that are not correct programs, with the reason kerf
// must give.
std::map<std::string, std::string> refused_files() {
  std::map<std::string, std::string> out;
  std::ifstream f(KERF_REFUSED_TSV);
  std::string line;
  while (std::getline(f, line)) {
    const std::size_t tab = line.find('\t');
    if (line.empty() || line[0] == '#' || tab == std::string::npos) continue;
    out[(fs::path(KERF_TEST_DATA_DIR) / line.substr(0, tab)).string()] = line.substr(tab + 1);
  }
  return out;
}

struct Case {
  std::string file;
  double tol;
};

class FitBoardCorpus : public ::testing::TestWithParam<Case> {};

TEST_P(FitBoardCorpus, NoSegmentIsRefused) {
  const Case c = GetParam();
  const std::map<std::string, std::string> bad_programs = refused_files();
  const auto refused_file = bad_programs.find(c.file);
  if (refused_file != bad_programs.end()) {  // not a correct program: refused with its reason
    io::PointFile in;
    std::string error;
    EXPECT_FALSE(job::read_gcode_job(c.file, in, error));
    EXPECT_NE(error.find(refused_file->second), std::string::npos) << error;
    return;
  }
  std::string how;
  const io::PointFile in = read_paths(c.file, how);
  ASSERT_FALSE(in.points.empty()) << c.file << ": " << how;
  control::FittedJob fitted;
  std::string error;
  Status st = Status::ok;
  ASSERT_TRUE(control::fit_paths(in, job::Criterion::band, c.tol, 10.0, fitted, error, st)) << how << ": " << error;
  std::size_t checked = 0, refused = 0;
  for (std::size_t p = 0; p < fitted.job.paths.size(); ++p) {
    const control::CutPath& path = fitted.job.paths[p];
    // The rapid to the pierce point ends there on the board.
    Vec2<double> at = position_over_modbus(path.start);
    for (std::size_t k = 0; k < path.segments.size(); ++k) {
      const hal::SegmentCommand d = over_modbus(path.segments[k]);
      motion::PathSegment<double> seg;
      seg.geometry = d.kind == SegmentKind::arc ? Segment<double>::arc(at, d.end, d.centre, d.dir)
                                                : Segment<double>::line(at, d.end);
      seg.feed = d.feed;
      if (!motion::prepare_segment(seg).ok()) {
        if (++refused <= 5)
          ADD_FAILURE() << c.file << " tol " << c.tol << ": path " << p + 1 << " segment " << k + 1
                        << " refused by the board";
      }
      // And over a link that carries doubles (CAN): the same geometry.
      motion::PathSegment<double> exact;
      const hal::SegmentCommand& s = path.segments[k];
      exact.geometry = s.kind == SegmentKind::arc ? Segment<double>::arc(at, s.end, s.centre, s.dir)
                                                  : Segment<double>::line(at, s.end);
      exact.feed = s.feed;
      EXPECT_TRUE(motion::prepare_segment(exact).ok());
      at = d.end;
      ++checked;
    }
  }
  EXPECT_EQ(refused, 0u);
  EXPECT_GT(checked, 0u);
  std::printf("%s tol %g (%s): %zu paths, %zu segments checked, %zu refused, %zu arcs run as chords\n",
              fs::path(c.file).filename().string().c_str(), c.tol, how.c_str(), fitted.job.paths.size(), checked,
              refused, fitted.lines_for_arcs);
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const std::string& f : gcode_files())
    for (double tol : {0.005, 0.01, 0.025, 0.05, 0.1}) out.push_back({f, tol});
  return out;
}

std::string case_name(const ::testing::TestParamInfo<Case>& i) {
  std::string s = fs::path(i.param.file).stem().string() + "_tol" + std::to_string(static_cast<int>(std::lround(i.param.tol * 1000)));
  for (char& ch : s)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(Files, FitBoardCorpus, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace kerf
