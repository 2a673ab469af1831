// `kerf fit --format gcode|svg`: the G-code read back by kerf's reader gives
// the pieces as written, the independent weld checker finds every point (and
// the path between them) within tol, and the SVG holds one piece path per
// piece, every point, the band, and a deviation curve inside the ±tol lines.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "job/biarc_job.hpp"
#include "job/fit_job.hpp"
#include "io/fit_gcode.hpp"
#include "io/fit_svg.hpp"
#include "job/gcode_reader.hpp"
#include "weld_checker.hpp"

namespace {

using kerf::Vec2;
using Piece = kerf::fit::Piece<double>;

// Two paths: a wave (with a ripple of that amplitude) and a spiral turn, in mm.
struct Job {
  std::vector<Vec2<double>> points;
  std::vector<std::size_t> begin;
};

Job two_paths(double ripple = 0.02) {
  Job j;
  j.begin.push_back(0);
  for (int i = 0; i <= 240; ++i) {
    const double x = 0.25 * i;
    j.points.push_back({x, 8.0 * std::sin(x / 9.0) + ripple * std::sin(3.1 * i)});
  }
  j.begin.push_back(j.points.size());
  for (int i = 0; i <= 160; ++i) {
    const double t = 0.03 * i;
    const double r = 20.0 + 2.0 * t;
    j.points.push_back({30.0 + r * std::cos(t), -40.0 + r * std::sin(t)});
  }
  return j;
}

// The job fitted path by path; first/last index the whole job.
std::vector<Piece> fit(const Job& j, double tol, const std::string& criterion) {
  std::vector<Piece> all;
  for (std::size_t p = 0; p < j.begin.size(); ++p) {
    const std::size_t b = j.begin[p];
    const std::size_t e = p + 1 < j.begin.size() ? j.begin[p + 1] : j.points.size();
    const std::vector<Vec2<double>> pts(j.points.begin() + static_cast<long>(b),
                                        j.points.begin() + static_cast<long>(e));
    std::vector<Piece> pieces;
    std::string error;
    kerf::Status status{};
    if (criterion == "biarc") {
      std::vector<kerf::fit::BiarcPiece<double>> biarcs;
      kerf::fit::Fit<double> f{};
      EXPECT_TRUE(kerf::job::fit_biarc_path(pts, {}, tol, biarcs, f, error, status)) << error;
      for (const auto& bi : biarcs)
        for (const auto& g : bi.arc) pieces.push_back({bi.first, bi.last, g, bi.error});
    } else {
      EXPECT_TRUE(kerf::job::fit_job(pts, {}, tol, *kerf::job::parse_criterion(criterion), pieces, error, status)) << error;
    }
    for (Piece& pc : pieces) {
      pc.first += static_cast<std::uint32_t>(b);
      pc.last += static_cast<std::uint32_t>(b);
      all.push_back(pc);
    }
  }
  return all;
}

kerf::io::GcodeFit gcode_of(const Job& j, const std::vector<Piece>& pieces, double tol) {
  kerf::io::GcodeFit g;
  g.pieces = {pieces.data(), pieces.size()};
  g.points = {j.points.data(), j.points.size()};
  g.feed = 1500;
  g.comment = "test";
  g.decimals = kerf::io::gcode_decimals(g, tol, 3);
  return g;
}

// The input as G-code the weld checker can compare against: the same lines
// (the G0s as the fit writes them, with `decimals`), with each path as the G1
// polyline through its points (12 decimals).
std::string polyline_gcode(const Job& j, int decimals) {
  std::string out = "; test\nG21 G90 G17\n";
  char buf[128];
  for (std::size_t p = 0; p < j.begin.size(); ++p) {
    const std::size_t b = j.begin[p];
    const std::size_t e = p + 1 < j.begin.size() ? j.begin[p + 1] : j.points.size();
    std::snprintf(buf, sizeof buf, "G0 X%.*f Y%.*f\n", decimals, j.points[b].x, decimals,
                  j.points[b].y);
    out += buf;
    for (std::size_t i = b + 1; i < e; ++i) {
      std::snprintf(buf, sizeof buf, "G1 X%.12f Y%.12f%s\n", j.points[i].x, j.points[i].y,
                    i == b + 1 ? " F1500" : "");
      out += buf;
    }
  }
  out += "M2\n";
  return out;
}

// Reads the G-code back: every feed move against the piece it was written for.
void expect_reads_back(const std::string& text, const std::vector<Piece>& written,
                       std::size_t paths, int decimals) {
  const kerf::job::GcodeFile f = kerf::job::parse_gcode(text, "fit.nc");
  ASSERT_TRUE(f.ok) << kerf::job::describe_error(f);
  const double eps = std::pow(10.0, -decimals) * 0.51;
  std::size_t k = 0, rapids = 0;
  for (const kerf::job::GBlock& bl : f.blocks) {
    if (!bl.moves) continue;
    if (bl.motion == kerf::job::Motion::rapid) {
      ++rapids;
      continue;
    }
    ASSERT_LT(k, written.size()) << "more moves than pieces at line " << bl.line;
    const kerf::Segment<double>& s = written[k].segment;
    EXPECT_EQ(bl.motion == kerf::job::Motion::linear, !s.is_arc()) << "line " << bl.line;
    if (s.is_arc()) {
      EXPECT_EQ(bl.motion == kerf::job::Motion::ccw, s.dir > 0) << "line " << bl.line;
    }
    EXPECT_NEAR(bl.start[0], s.start.x, eps) << "line " << bl.line;
    EXPECT_NEAR(bl.start[1], s.start.y, eps) << "line " << bl.line;
    EXPECT_NEAR(bl.end_pos[0], s.end.x, eps) << "line " << bl.line;
    EXPECT_NEAR(bl.end_pos[1], s.end.y, eps) << "line " << bl.line;
    if (s.is_arc()) {
      EXPECT_NEAR(bl.centre[0], s.centre.x, 2 * eps) << "line " << bl.line;
      EXPECT_NEAR(bl.centre[1], s.centre.y, 2 * eps) << "line " << bl.line;
    }
    ++k;
  }
  EXPECT_EQ(k, written.size());
  EXPECT_EQ(rapids, paths);
}

// max_ratio: output moves / input moves the fit must beat.
void check_gcode(const std::string& criterion, double tol, double max_ratio, double ripple) {
  const Job j = two_paths(ripple);
  const std::vector<Piece> pieces = fit(j, tol, criterion);
  ASSERT_FALSE(pieces.empty());
  const kerf::io::GcodeFit g = gcode_of(j, pieces, tol);
  EXPECT_LE(kerf::io::written_deviation(g), tol);
  const std::string text = kerf::io::format_fit_gcode(g);
  expect_reads_back(text, pieces, j.begin.size(), g.decimals);
  // The referee, with its own parser: the path within tol of the polyline.
  const kerf_test::WeldCheck c = kerf_test::check_weld(polyline_gcode(j, g.decimals), text, tol);
  EXPECT_TRUE(c.ok) << c.why;
  EXPECT_LE(c.max_deviation, tol);
  EXPECT_LT(static_cast<double>(c.output_moves), max_ratio * static_cast<double>(c.input_moves));
}

TEST(FitGcode, BandFitReadsBackAndStaysWithinTol) { check_gcode("band", 0.02, 0.25, 0.02); }

// Without the ripple: estimated tangents on it cost many biarcs (and time).
TEST(FitGcode, BiarcFitReadsBackAndStaysWithinTol) { check_gcode("biarc", 0.02, 0.25, 0.0); }

TEST(FitGcode, VertexFitKeepsEveryPointWithinTolAfterRounding) {
  const double tol = 0.01;
  const Job j = two_paths();
  const std::vector<Piece> pieces = fit(j, tol, "vertex");
  const kerf::io::GcodeFit g = gcode_of(j, pieces, tol);
  EXPECT_LE(kerf::io::written_deviation(g), tol);
  expect_reads_back(kerf::io::format_fit_gcode(g), pieces, j.begin.size(), g.decimals);
}

// The checks above can fail: one decimal moves the pieces by up to 0.05 mm.
TEST(FitGcode, TooFewDecimalsAreCaught) {
  const double tol = 0.02;
  const Job j = two_paths();
  const std::vector<Piece> pieces = fit(j, tol, "band");
  kerf::io::GcodeFit g = gcode_of(j, pieces, tol);
  EXPECT_GE(g.decimals, 3);
  g.decimals = 1;
  EXPECT_GT(kerf::io::written_deviation(g), tol);
  const kerf_test::WeldCheck c =
      kerf_test::check_weld(polyline_gcode(j, 1), kerf::io::format_fit_gcode(g), tol);
  EXPECT_FALSE(c.ok);
}

// --- SVG -------------------------------------------------------------------

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The value of attribute `name` of the first element that starts with `open`.
std::string attribute(const std::string& text, const std::string& open, const std::string& name) {
  const std::size_t at = text.find(open);
  if (at == std::string::npos) return {};
  const std::size_t end = text.find('>', at);
  const std::string element = text.substr(at, end - at);
  const std::size_t a = element.find(" " + name + "=\"");
  if (a == std::string::npos) return {};
  const std::size_t from = a + name.size() + 3;
  return element.substr(from, element.find('"', from) - from);
}

// Every number -?D+(.D+)?([eE][-+]?D+)? in s, left to right. (Scanned by
// hand: GCC 12 warns falsely inside <regex> under ASan at -O1.)
std::vector<double> numbers(const std::string& s) {
  const auto digits = [&s](std::size_t k) {
    while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k])) != 0) ++k;
    return k;
  };
  std::vector<double> out;
  std::size_t k = 0;
  while (k < s.size()) {
    const std::size_t from = k;
    const std::size_t lead = s[k] == '-' ? k + 1 : k;
    std::size_t end = digits(lead);
    if (end == lead) {
      k = from + 1;
      continue;
    }
    if (end + 1 < s.size() && s[end] == '.' && digits(end + 1) > end + 1) end = digits(end + 1);
    if (end < s.size() && (s[end] == 'e' || s[end] == 'E')) {
      const bool signed_exp = end + 1 < s.size() && (s[end + 1] == '-' || s[end + 1] == '+');
      const std::size_t sign = signed_exp ? end + 2 : end + 1;
      if (digits(sign) > sign) end = digits(sign);
    }
    out.push_back(std::strtod(s.substr(from, end - from).c_str(), nullptr));
    k = end;
  }
  return out;
}

std::string svg_of(const Job& j, const std::vector<Piece>& pieces, double tol) {
  kerf::io::FitPlot plot;
  plot.points = {j.points.data(), j.points.size()};
  plot.path_begin = j.begin;
  plot.pieces = {pieces.data(), pieces.size()};
  plot.tol_left = plot.tol_right = tol;
  plot.title = "fit <test> & more";
  return kerf::io::format_fit_svg(plot);
}

void check_svg(const std::string& criterion, double tol, double ripple) {
  const Job j = two_paths(ripple);
  const std::vector<Piece> pieces = fit(j, tol, criterion);
  const std::string svg = svg_of(j, pieces, tol);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_EQ(count(svg, "<path class=\"piece\""), pieces.size());
  EXPECT_EQ(count(svg, "<circle class=\"pt\""), j.points.size());
  EXPECT_EQ(count(svg, "<path class=\"band\""), j.begin.size());  // one per path
  EXPECT_GT(std::strtod(attribute(svg, "<path class=\"band\"", "stroke-width").c_str(), nullptr), 0);
  EXPECT_NE(svg.find("fit &lt;test&gt; &amp; more"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);

  // The deviation curve: a vertex per point, between the two limit lines.
  EXPECT_EQ(count(svg, "<polyline class=\"dev\""), 1u);
  const std::vector<double> dev = numbers(attribute(svg, "<polyline class=\"dev\"", "points"));
  ASSERT_EQ(dev.size(), 2 * j.points.size());
  ASSERT_EQ(count(svg, "<line class=\"limit\""), 2u);
  const std::size_t second = svg.find("<line class=\"limit\"", svg.find("<line class=\"limit\"") + 1);
  const double top = std::strtod(attribute(svg, "<line class=\"limit\"", "y1").c_str(), nullptr);
  const double bottom =
      std::strtod(attribute(svg.substr(second), "<line class=\"limit\"", "y1").c_str(), nullptr);
  ASSERT_LT(top, bottom);  // +tol is drawn above -tol (y down)
  double x_before = -1;
  bool off_centre = false;
  for (std::size_t i = 0; i < dev.size(); i += 2) {
    EXPECT_TRUE(std::isfinite(dev[i]) && std::isfinite(dev[i + 1]));
    EXPECT_GE(dev[i], x_before) << "distance along the path goes back at point " << i / 2;
    x_before = dev[i];
    EXPECT_GE(dev[i + 1], top - 0.01) << "point " << i / 2 << " over +tol";
    EXPECT_LE(dev[i + 1], bottom + 0.01) << "point " << i / 2 << " under -tol";
    off_centre = off_centre || std::fabs(dev[i + 1] - (top + bottom) / 2) > 1.0;
  }
  EXPECT_TRUE(off_centre) << "a fit at tol deviates visibly somewhere";
  for (const double v : numbers(svg)) ASSERT_TRUE(std::isfinite(v));
}

TEST(FitSvg, BandFitPlotHasPiecesPointsBandAndDeviation) { check_svg("band", 0.05, 0.02); }

TEST(FitSvg, BiarcFitPlotHasBothArcsOfEachBiarc) { check_svg("biarc", 0.05, 0.0); }

// The deviation check above can fail: pieces fitted at 4 * tol leave points
// outside the ±tol lines drawn at tol.
TEST(FitSvg, DeviationOverTolIsVisibleOutsideTheLimits) {
  const Job j = two_paths();
  const std::vector<Piece> pieces = fit(j, 0.2, "band");
  const std::string svg = svg_of(j, pieces, 0.05);
  const std::vector<double> dev = numbers(attribute(svg, "<polyline class=\"dev\"", "points"));
  const double top = std::strtod(attribute(svg, "<line class=\"limit\"", "y1").c_str(), nullptr);
  const std::size_t second = svg.find("<line class=\"limit\"", svg.find("<line class=\"limit\"") + 1);
  const double bottom =
      std::strtod(attribute(svg.substr(second), "<line class=\"limit\"", "y1").c_str(), nullptr);
  std::size_t outside = 0;
  for (std::size_t i = 1; i < dev.size(); i += 2)
    outside += dev[i] < top - 0.01 || dev[i] > bottom + 0.01 ? 1 : 0;
  EXPECT_GT(outside, 0u);
}

}  // namespace

namespace {

// A file name with a line end stays inside the first comment line.
TEST(FitGcode, CommentCannotBreakTheFile) {
  const Job j = two_paths();
  const std::vector<Piece> pieces = fit(j, 0.05, "band");
  kerf::io::GcodeFit g = gcode_of(j, pieces, 0.05);
  g.comment = "a\nG0 X999\rb";
  const std::string text = kerf::io::format_fit_gcode(g);
  EXPECT_EQ(text.rfind("; a?G0 X999?b\nG21 G90 G17\n", 0), 0u) << text.substr(0, 60);
  const kerf::job::GcodeFile f = kerf::job::parse_gcode(text, "fit.nc");
  ASSERT_TRUE(f.ok) << kerf::job::describe_error(f);
}

}  // namespace
