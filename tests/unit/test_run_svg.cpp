// The run plot (io/run_svg): its pieces, arc flags, y flip, torch runs, size.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "io/run_svg.hpp"

namespace {

using kerf::io::format_run_svg;
using kerf::io::RunPlot;
using kerf::io::TraceSample;
using V = kerf::Vec2<double>;
using Seg = kerf::Segment<double>;

constexpr double kPi = 3.14159265358979323846;

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

// The value of attribute `name` of each element that starts with `open`.
std::vector<std::string> attrs(const std::string& svg, const std::string& open, const std::string& name) {
  std::vector<std::string> out;
  for (std::size_t p = svg.find(open); p != std::string::npos; p = svg.find(open, p + 1)) {
    const std::size_t end = svg.find('>', p);
    const std::size_t a = svg.find(" " + name + "=\"", p);
    if (a == std::string::npos || a > end) continue;
    const std::size_t from = a + name.size() + 3;
    out.push_back(svg.substr(from, svg.find('"', from) - from));
  }
  return out;
}

// The XY panel only (the legend holds sample elements of the same classes).
std::string xy_part(const std::string& svg) {
  const std::size_t a = svg.find("<g id=\"xy\">");
  const std::size_t b = svg.find("<g id=\"speed\">");
  EXPECT_NE(a, std::string::npos);
  EXPECT_NE(b, std::string::npos);
  return svg.substr(a, b - a);
}

struct SvgArc {
  V from, to;
  double rx, ry;
  int large, sweep;
};

// A piece's d: "M x y A rx ry rot large sweep x y" (one arc).
SvgArc parse_arc(const std::string& d) {
  std::istringstream in(d);
  char m = 0, a = 0;
  SvgArc r{};
  double rot = 0;
  in >> m >> r.from.x >> r.from.y >> a >> r.rx >> r.ry >> rot >> r.large >> r.sweep >> r.to.x >> r.to.y;
  EXPECT_EQ(m, 'M');
  EXPECT_EQ(a, 'A');
  EXPECT_FALSE(in.fail()) << d;
  return r;
}

// The centre SVG's renderer puts a circular arc on (SVG 1.1 F.6.5, rx = ry, no
// rotation): on the left or right of the chord by whether the flags differ.
V svg_centre(const SvgArc& a) {
  const V half{(a.from.x - a.to.x) / 2, (a.from.y - a.to.y) / 2};
  const double d2 = half.norm2();
  const double k = std::sqrt(std::fmax(a.rx * a.rx - d2, 0.0) / d2) * (a.large != a.sweep ? 1 : -1);
  return V{k * half.y + (a.from.x + a.to.x) / 2, -k * half.x + (a.from.y + a.to.y) / 2};
}

// Expected flags from the world geometry, worked out apart from the code: the
// swept angle from the polar angles of the ends, and the y flip reversing the
// angle direction (SVG's positive sweep is the y-down screen's).
void expected_flags(const Seg& s, int& large, int& sweep) {
  const double as = std::atan2(s.start.y - s.centre.y, s.start.x - s.centre.x);
  const double ae = std::atan2(s.end.y - s.centre.y, s.end.x - s.centre.x);
  double ccw = std::fmod(ae - as + 4 * kPi, 2 * kPi);  // CCW angle from start to end
  const double swept = s.dir > 0 ? ccw : 2 * kPi - ccw;
  large = swept > kPi ? 1 : 0;
  sweep = s.dir > 0 ? 0 : 1;
}

void check_arc(const Seg& s, int want_large) {
  RunPlot plot;
  plot.pieces = {s};
  plot.piece_path = {0};
  const std::string svg = format_run_svg(plot);
  const auto ds = attrs(xy_part(svg), "<path class=\"piece\"", "d");
  ASSERT_EQ(ds.size(), 1u);
  const SvgArc a = parse_arc(ds[0]);
  int large = -1, sweep = -1;
  expected_flags(s, large, sweep);
  EXPECT_EQ(large, want_large);  // the helper agrees with the known shape
  EXPECT_EQ(a.large, large) << ds[0];
  EXPECT_EQ(a.sweep, sweep) << ds[0];
  // The renderer's centre is the piece's centre mapped to the screen.
  const double scale = a.rx / s.radius();
  const V want{a.from.x + (s.centre.x - s.start.x) * scale, a.from.y - (s.centre.y - s.start.y) * scale};
  const V got = svg_centre(a);
  EXPECT_NEAR(got.x, want.x, 0.05) << ds[0];
  EXPECT_NEAR(got.y, want.y, 0.05) << ds[0];
}

TEST(RunSvg, CcwQuarterCircle) { check_arc(Seg::arc(V{10, 0}, V{0, 10}, V{0, 0}, +1), 0); }
TEST(RunSvg, CwQuarterCircle) { check_arc(Seg::arc(V{10, 0}, V{0, -10}, V{0, 0}, -1), 0); }
TEST(RunSvg, CcwThreeQuarters) { check_arc(Seg::arc(V{10, 0}, V{0, -10}, V{0, 0}, +1), 1); }
TEST(RunSvg, CwThreeQuarters) { check_arc(Seg::arc(V{15, 5}, V{5, 15}, V{5, 5}, -1), 1); }

TEST(RunSvg, OnePiecePathPerPiece) {
  RunPlot plot;
  plot.paths = {{V{0, 0}, V{10, 0}, V{10, 10}}, {V{20, 0}, V{30, 0}}};
  plot.pieces = {Seg::line(V{0, 0}, V{10, 0}), Seg::arc(V{10, 0}, V{10, 10}, V{10, 5}, 1),
                 Seg::line(V{20, 0}, V{30, 0}), Seg::arc(V{40, 0}, V{40, 0}, V{45, 0}, -1)};
  plot.piece_path = {0, 0, 1, 2};
  plot.tol = 0.5;
  const std::string xy = xy_part(format_run_svg(plot));
  const auto ds = attrs(xy, "<path class=\"piece\"", "d");
  ASSERT_EQ(ds.size(), plot.pieces.size());
  EXPECT_EQ(count(ds[0], "L"), 1u);
  EXPECT_EQ(count(ds[0], "A"), 0u);
  EXPECT_EQ(count(ds[1], "A"), 1u);
  EXPECT_EQ(count(ds[3], "A"), 2u);  // a full circle is drawn as two halves
  EXPECT_EQ(attrs(xy, "<path class=\"piece\"", "data-path"),
            (std::vector<std::string>{"0", "0", "1", "2"}));
  EXPECT_EQ(attrs(xy, "<circle class=\"pt\"", "cx").size(), 5u);
}

TEST(RunSvg, YIsFlipped) {
  RunPlot plot;
  plot.paths = {{V{0, 0}, V{0, 10}}};
  const auto cy = attrs(xy_part(format_run_svg(plot)), "<circle class=\"pt\"", "cy");
  ASSERT_EQ(cy.size(), 2u);
  EXPECT_GT(std::stod(cy[0]), std::stod(cy[1]) + 100);  // y = 10 is drawn higher up
}

TEST(RunSvg, TraceSplitsIntoTorchRuns) {
  RunPlot plot;
  const bool torch[] = {true, true, false, false, false, true, true};
  for (int i = 0; i < 7; ++i)
    plot.trace.push_back(TraceSample{0.1 * i, V{double(i), double(i % 2)}, std::uint32_t(i + 1), torch[i]});
  const std::string svg = format_run_svg(plot);
  const std::string xy = xy_part(svg);
  const auto cut = attrs(xy, "<polyline class=\"cut\"", "points");
  const auto rapid = attrs(xy, "<polyline class=\"rapid\"", "points");
  ASSERT_EQ(cut.size(), 2u);
  ASSERT_EQ(rapid.size(), 1u);
  // Each run starts at the previous run's last sample.
  EXPECT_EQ(count(cut[0], ","), 2u);   // samples 0-1
  EXPECT_EQ(count(rapid[0], ","), 4u); // samples 1-4
  EXPECT_EQ(count(cut[1], ","), 3u);   // samples 4-6
  EXPECT_EQ(count(xy, "<circle class=\"pierce\""), 2u);  // samples 0 and 5
  const std::string speed = svg.substr(svg.find("<g id=\"speed\">"));
  EXPECT_EQ(count(speed, "<rect class=\"on\""), 2u);
  EXPECT_EQ(count(speed, "<polyline class=\"speed\""), 1u);
  EXPECT_EQ(count(speed, "no trace"), 0u);
}

TEST(RunSvg, EmptyTraceStillGivesAPlot) {
  RunPlot plot;
  plot.title = "a <job> & \"more\"";
  const std::string svg = format_run_svg(plot);
  EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7);
  EXPECT_EQ(count(svg, "<polyline"), 0u);
  EXPECT_EQ(count(svg, "no trace"), 1u);
  EXPECT_EQ(count(svg, "a &lt;job&gt; &amp; &quot;more&quot;"), 1u);
}

TEST(RunSvg, TitleKeepsUtf8AndDropsWhatXmlForbids) {
  RunPlot plot;
  plot.title = "job \u00b1 \xff\x01 \xe2\x82";  // good UTF-8, a stray byte, a control, a cut sequence
  const std::string svg = format_run_svg(plot);
  EXPECT_EQ(count(svg, "job \u00b1 ?\? ?\?</text>"), 1u);
}

TEST(RunSvg, NearlyStraightArcIsDrawnAsItsChord) {
  RunPlot plot;
  plot.pieces = {Seg::arc(V{0, 0}, V{10, 0}, V{5, -1e9}, -1)};
  const auto ds = attrs(xy_part(format_run_svg(plot)), "<path class=\"piece\"", "d");
  ASSERT_EQ(ds.size(), 1u);
  EXPECT_EQ(count(ds[0], "L"), 1u);
  EXPECT_EQ(count(ds[0], "A"), 0u);
}

TEST(RunSvg, LongTraceIsDecimatedKeepingExtremes) {
  RunPlot plot;
  const std::size_t n = 200000;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = i == 123457 ? 50.0 : 0.0;  // one spike
    plot.trace.push_back(TraceSample{1e-3 * double(i), V{1e-3 * double(i), y}, 1, true});
  }
  const std::string svg = format_run_svg(plot);
  const auto cut = attrs(xy_part(svg), "<polyline class=\"cut\"", "points");
  ASSERT_EQ(cut.size(), 1u);
  EXPECT_LE(count(cut[0], ","), kerf::io::kMaxPolylineVertices);
  EXPECT_GT(count(cut[0], ","), kerf::io::kMaxPolylineVertices / 4);
  std::set<std::string> ys;
  std::istringstream in(cut[0]);
  for (std::string v; in >> v;) ys.insert(v.substr(v.find(',') + 1));
  EXPECT_EQ(ys.size(), 2u);  // the spike survived
  const auto speed = attrs(svg, "<polyline class=\"speed\"", "points");
  ASSERT_EQ(speed.size(), 1u);
  EXPECT_LE(count(speed[0], ","), kerf::io::kMaxPolylineVertices);
  EXPECT_LT(svg.size(), 400000u);
}

}  // namespace

namespace {

// Dwells and pauses are marked where they happened, a square for a dwell and
// the square turned 45 degrees for a pause, each with its text as a title.
TEST(RunSvg, MarksDwellsAndPausesWhereTheyHappened) {
  RunPlot plot;
  plot.paths = {{V{0, 0}, V{10, 0}}};
  plot.pieces = {Seg::line(V{0, 0}, V{10, 0})};
  plot.piece_path = {0};
  for (int i = 0; i <= 10; ++i) plot.trace.push_back({0.1 * i, V{static_cast<double>(i), 0}, 1, true});
  plot.marks = {{V{10, 0}, "dwell", "dwell 0.5 s"}, {V{0, 0}, "pause", "pause (M0) & <go>"}};
  const std::string xy = xy_part(format_run_svg(plot));
  const std::vector<std::string> dx = attrs(xy, "<rect class=\"dwell\"", "x");
  const std::vector<std::string> px = attrs(xy, "<rect class=\"pause\"", "x");
  ASSERT_EQ(dx.size(), 1u);
  ASSERT_EQ(px.size(), 1u);
  EXPECT_GT(std::stod(dx[0]), std::stod(px[0]));  // the dwell at x = 10, right of the pause at 0
  EXPECT_EQ(attrs(xy, "<rect class=\"pause\"", "transform").size(), 1u);
  EXPECT_EQ(count(xy, "<title>dwell 0.5 s</title>"), 1u);
  EXPECT_EQ(count(xy, "<title>pause (M0) &amp; &lt;go></title>"), 1u);
  // No marks, no legend entry for them.
  plot.marks.clear();
  EXPECT_EQ(count(format_run_svg(plot), "class=\"dwell\""), 0u);
}

}  // namespace
