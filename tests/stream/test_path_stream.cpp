// A path fitted in a bounded window (control/path_stream.hpp) against the
// whole-file fit (control/fit_paths.hpp), on every G-code file in
// tests/data/gcode: with a window that holds the path, the same segments
// bit for bit; with a small one (forced commits), a chain of segments
// within tol of every point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "control/path_stream.hpp"
#include "job/gcode_program.hpp"

namespace {

using namespace kerf;
using control::StreamedSegment;

constexpr double kTol = 0.025;
constexpr double kFeed = 50.0;

std::vector<std::string> corpus() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(KERF_GCODE_DIR))
    if (job::is_gcode_path(e.path().string())) files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

struct Path {
  std::vector<Vec2<double>> pts;
  std::vector<std::size_t> lines;
  double tol = kTol;
};

std::vector<Path> paths_of(const std::string& file) {
  job::GcodeProgram prog;
  std::string error;
  std::vector<Path> out;
  // A few corpus files are refused on purpose (tests/contract/refused.tsv).
  if (!job::read_gcode_program(file, job::InterpSettings{}, job::MachineState{}, prog, error)) return out;
  const io::PointFile& in = prog.points;
  for (std::size_t p = 0; p < in.path_begin.size(); ++p) {
    const std::size_t b = in.path_begin[p];
    const std::size_t e = p + 1 < in.path_begin.size() ? in.path_begin[p + 1] : in.points.size();
    Path path;
    path.pts.assign(in.points.begin() + static_cast<std::ptrdiff_t>(b), in.points.begin() + static_cast<std::ptrdiff_t>(e));
    path.lines.assign(in.point_lines.begin() + static_cast<std::ptrdiff_t>(b),
                      in.point_lines.begin() + static_cast<std::ptrdiff_t>(e));
    const double t = prog.paths[p].tol;
    path.tol = t > 0 ? std::min(t, kTol) : kTol;
    out.push_back(std::move(path));
  }
  return out;
}

// The path through the fitter: its segments, or an error.
bool stream(control::PathStreamFitter& f, const Path& path, std::vector<StreamedSegment>& out, std::string& error) {
  out.clear();
  const control::PathStreamFitter::Sink sink = [&](const StreamedSegment& s) {
    out.push_back(s);
    return true;
  };
  Status st = Status::ok;
  f.begin_path("corpus", 0, path.tol);
  for (std::size_t k = 0; k < path.pts.size(); ++k)
    if (!f.push(path.pts[k], path.lines[k], sink, error, st)) return false;
  return f.end_path(sink, error, st);
}

bool same_bits(const hal::SegmentCommand& a, const hal::SegmentCommand& b) {
  return a.kind == b.kind && std::memcmp(&a.end, &b.end, sizeof a.end) == 0 &&
         std::memcmp(&a.centre, &b.centre, sizeof a.centre) == 0 && a.dir == b.dir &&
         std::memcmp(&a.feed, &b.feed, sizeof a.feed) == 0 && a.torch == b.torch;
}

// Distance from p to the segment's line or full circle: the vertex
// criterion's measure (job/check_fit.hpp), which lets a point overshoot a
// line's end along it.
double off(const StreamedSegment& s, Vec2<double> p) {
  const hal::SegmentCommand& c = s.cmd;
  if (c.kind == SegmentKind::arc) return std::fabs(distance(p, c.centre) - distance(s.from, c.centre));
  const Vec2<double> d = c.end - s.from;
  const double len = std::sqrt(d.x * d.x + d.y * d.y);
  if (len == 0) return distance(p, s.from);
  return std::fabs((p.x - s.from.x) * d.y - (p.y - s.from.y) * d.x) / len;
}

TEST(PathStream, WindowHoldingThePathGivesTheWholeFileSegments) {
  for (const job::Criterion criterion : {job::Criterion::band, job::Criterion::vertex}) {
    control::PathStreamFitter f;
    std::string error;
    ASSERT_TRUE(f.start(criterion, job::Numeric::floating, kFeed, control::PathStreamFitter::kMaxWindow, error));
    std::size_t compared = 0, files = 0;
    for (const std::string& file : corpus()) {
      const std::vector<Path> paths = paths_of(file);
      files += paths.empty() ? 0 : 1;
      for (const Path& path : paths) {
        if (path.pts.size() > control::PathStreamFitter::kMaxWindow) continue;  // the next test's case
        // Vertex (not the configuration's default) on the shorter paths only: test time.
        if (criterion == job::Criterion::vertex && path.pts.size() > 500) continue;
        io::PointFile one;
        one.file = "corpus";
        one.points = path.pts;
        one.point_lines = path.lines;
        control::FittedJob whole;
        std::string why;
        Status st = Status::ok;
        const bool fitted = control::fit_paths(one, criterion, path.tol, kFeed, whole, why, st);
        std::vector<StreamedSegment> got;
        const bool streamed = stream(f, path, got, error);
        if (!fitted && why.find("shorter than the link") != std::string::npos) {  // nothing to cut either way
          EXPECT_TRUE(streamed && got.empty()) << file << ": " << error;
          continue;
        }
        ASSERT_EQ(streamed, fitted) << file << ": " << error << " / " << why;
        if (!fitted) {  // refused the same way
          EXPECT_EQ(error, why) << file;
          continue;
        }
        const control::CutPath& want = whole.job.paths.front();
        ASSERT_EQ(got.size(), want.segments.size()) << file;
        for (std::size_t k = 0; k < got.size(); ++k) {
          ASSERT_TRUE(same_bits(got[k].cmd, want.segments[k])) << file << " segment " << k;
          EXPECT_EQ(got[k].piece.first, whole.pieces[k].first);
          EXPECT_EQ(got[k].piece.last, whole.pieces[k].last);
        }
        EXPECT_EQ(std::memcmp(&got.front().from, &want.start, sizeof want.start), 0) << file;
        compared += got.size();
      }
    }
    EXPECT_GE(files, 15u);
    EXPECT_GT(compared, 200u);
    EXPECT_EQ(f.stats().forced, 0u);
  }
}

// A window far shorter than the paths: forced commits, counted, and every
// segment chains on from the last and stays within tol (plus the grid's
// rounding) of the points it was fitted to.
TEST(PathStream, SmallWindowStaysWithinTolAndCountsForcedCommits) {
  for (const job::Criterion criterion : {job::Criterion::vertex, job::Criterion::band}) {
    control::PathStreamFitter f;
    std::string error;
    ASSERT_TRUE(f.start(criterion, job::Numeric::floating, kFeed, 16, error));
    std::size_t checked = 0, refused = 0;
    for (const std::string& file : corpus()) {
      for (const Path& path : paths_of(file)) {
        std::vector<StreamedSegment> got;
        if (!stream(f, path, got, error)) {
          // Only where the whole-path fit refuses the path too (the fitter's
          // own limit, not the window's).
          io::PointFile one;
          one.file = "corpus";
          one.points = path.pts;
          one.point_lines = path.lines;
          control::FittedJob whole;
          std::string why;
          Status st = Status::ok;
          EXPECT_FALSE(control::fit_paths(one, criterion, path.tol, kFeed, whole, why, st)) << file << ": " << error;
          ++refused;
          continue;
        }
        std::vector<Vec2<double>> distinct;  // streamed pieces count the distinct points
        for (const Vec2<double>& p : path.pts)
          if (distinct.empty() || !(distinct.back() == p)) distinct.push_back(p);
        for (std::size_t k = 0; k < got.size(); ++k) {
          if (k > 0) {
            ASSERT_EQ(std::memcmp(&got[k].from, &got[k - 1].cmd.end, sizeof got[k].from), 0) << file;
          }
          if (path.pts.size() <= 16) continue;  // fitted whole: indices count every point
          // A piece may run as several segments (motion/segment_contract.hpp):
          // each of its points within reach of one of them.
          std::size_t e = k;
          while (e + 1 < got.size() && got[e + 1].piece.first == got[k].piece.first &&
                 got[e + 1].piece.last == got[k].piece.last)
            ++e;
          for (std::uint64_t i = got[k].piece.first; i <= got[k].piece.last; ++i) {
            double d = 1e9;
            for (std::size_t j = k; j <= e; ++j) d = std::min(d, off(got[j], distinct[i]));
            ASSERT_LE(d, path.tol + 0.0015) << file << " segment " << k << " point " << i;
            ++checked;
          }
          k = e;
        }
      }
    }
    EXPECT_LE(refused, 3u);
    EXPECT_GT(checked, 10000u);
    EXPECT_GT(f.stats().forced, 0u) << "the window never forced a commit: the test misses its case";
    EXPECT_GT(f.stats().streamed_paths, 0u);
  }
}

TEST(PathStream, RefusesAWindowOutOfRange) {
  control::PathStreamFitter f;
  std::string error;
  EXPECT_FALSE(f.start(job::Criterion::vertex, job::Numeric::floating, kFeed, 8, error));
  EXPECT_NE(error.find("16 to 4096"), std::string::npos) << error;
  EXPECT_FALSE(f.start(job::Criterion::vertex, job::Numeric::floating, kFeed, 5000, error));
}

}  // namespace

namespace {

// fit_paths (kerf sim, kerf run): a path longer than the window goes
// through it. A straight run of 10000 points is one piece for the whole
// path, so the window forces commits: counted in the job, and the segments
// still chain from the pierce point and pass within tol of every point.
TEST(PathStream, FitPathsStreamsAPathLongerThanTheWindow) {
  io::PointFile in;
  in.file = "long";
  for (int k = 0; k < 10000; ++k) {
    in.points.push_back({k * 0.01, 0.002 * std::sin(k * 0.1)});
    in.point_lines.push_back(static_cast<std::size_t>(k + 1));
  }
  in.path_begin = {0};
  control::FittedJob out;
  std::string error;
  Status st = Status::ok;
  ASSERT_TRUE(control::fit_paths(in, job::Criterion::vertex, kTol, kFeed, out, error, st)) << error;
  EXPECT_GT(out.job.forced_commits, 0u);
  ASSERT_EQ(out.job.paths.size(), 1u);
  const control::CutPath& path = out.job.paths.front();
  ASSERT_EQ(path.segments.size(), out.pieces.size());
  Vec2<double> from = path.start;
  for (std::size_t k = 0; k < path.segments.size(); ++k) {
    StreamedSegment s{path.segments[k], out.pieces[k], from};
    for (std::uint32_t i = out.pieces[k].first; i <= out.pieces[k].last; ++i)
      ASSERT_LE(off(s, in.points[i]), kTol + 0.0015) << "segment " << k << " point " << i;
    from = path.segments[k].end;
  }
  EXPECT_EQ(out.pieces.back().last, 9999u);
  EXPECT_LT(path.segments.size(), 20u);
}

}  // namespace

namespace {

std::size_t pieces_in(const std::vector<fit::Piece<double>>& pieces) {
  std::size_t n = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k)
    n += k == 0 || pieces[k].first != pieces[k - 1].first || pieces[k].last != pieces[k - 1].last;
  return n;
}

// Past the fit's reach (no forced commit in a path longer than the window)
// the streamed fit has the whole path's piece count, the fewest (fit/stream.hpp,
// "Exactness"). The pieces themselves may differ where the whole-file fit's
// tie-break picks another of several fewest-piece fits.
TEST(PathStream, NoForcedCommitGivesTheFewestPieces) {
  constexpr std::uint32_t kWindow = 256;
  // Vertex, paths up to 2000 points: the whole-path band fit of the long ones takes seconds.
  for (const job::Criterion criterion : {job::Criterion::vertex}) {
    control::PathStreamFitter f;
    std::string error;
    ASSERT_TRUE(f.start(criterion, job::Numeric::floating, kFeed, kWindow, error));
    std::size_t compared = 0;
    for (const std::string& file : corpus()) {
      for (const Path& path : paths_of(file)) {
        if (path.pts.size() <= kWindow || path.pts.size() > 2000) continue;
        const std::uint32_t forced_before = f.stats().forced;
        std::vector<StreamedSegment> got;
        if (!stream(f, path, got, error) || f.stats().forced != forced_before) continue;
        io::PointFile one;
        one.file = "corpus";
        one.points = path.pts;
        one.point_lines = path.lines;
        control::FittedJob whole;
        Status st = Status::ok;
        if (!control::fit_paths(one, criterion, path.tol, kFeed, whole, error, st)) continue;
        std::vector<fit::Piece<double>> streamed;
        for (const StreamedSegment& s : got) streamed.push_back(s.piece);
        EXPECT_EQ(pieces_in(streamed), pieces_in(whole.pieces)) << file;
        ++compared;
      }
    }
    EXPECT_GE(compared, 5u);
  }
}

}  // namespace
