#include "io/fit_svg.hpp"

#include <cmath>
#include <cstdio>

#include "io/fit_deviation.hpp"
#include "io/svg_parts.hpp"

// Text is built with += throughout (GCC bug 105329, see fit_output.cpp).

namespace kerf::io {

namespace {

using namespace svg;

// [begin, end) point ranges of the paths.
std::vector<std::pair<std::size_t, std::size_t>> path_ranges(const FitPlot& plot) {
  std::vector<std::size_t> b = plot.path_begin;
  if (b.empty()) b.push_back(0);
  std::vector<std::pair<std::size_t, std::size_t>> r;
  for (std::size_t p = 0; p < b.size(); ++p)
    r.emplace_back(b[p], p + 1 < b.size() ? b[p + 1] : plot.points.size());
  return r;
}

void legend(std::string& out, const FitPlot& plot, double band) {
  Legend row{out, kLeft, kLegendY};
  const auto item = [&](const std::string& swatch, const std::string& name) { row.item(swatch, name); };
  item("<circle class=\"pt key\" cx=\"10\" cy=\"0\" r=\"2\"/>",
       "input points (" + std::to_string(plot.points.size()) + ")");
  item("<line x1=\"0\" y1=\"0\" x2=\"20\" y2=\"0\" stroke=\"#1f77b4\" stroke-width=\"2\"/>",
       "fitted pieces (" + std::to_string(plot.pieces.size()) + ")");
  std::string name = "tolerance band \u00b1";
  label(name, band);
  name += " mm";
  item("<line class=\"bandkey\" x1=\"0\" y1=\"0\" x2=\"20\" y2=\"0\" stroke-width=\"8\"/>", name);
  item("<line class=\"dev\" x1=\"0\" y1=\"0\" x2=\"20\" y2=\"0\"/>", "deviation");
}

// The XY panel; returns its height in px.
double xy_panel(std::string& out, const FitPlot& plot, double band) {
  Box box;
  for (const Vec2<double>& p : plot.points) box.add(p);
  for (const fit::Piece<double>& pc : plot.pieces) {
    box.add(pc.segment.start);
    box.add(pc.segment.end);
    if (pc.segment.is_arc()) add_arc_points(box, pc.segment);
  }
  // Room for the band around the outermost points.
  const XyPanel panel = xy_panel_frame(out, box, band, kLeft, kTopY, kPlotWidth, kMaxTopHeight);
  const XyMap& m = panel.map;
  const double scale = m.scale;
  const double height = panel.height;

  // The band: the input polyline, stroked as wide as the band, under the rest.
  for (const auto& [b, e] : path_ranges(plot)) {
    out += "<path class=\"band\" stroke-width=\"";
    num(out, 2 * band * scale);
    out += "\" d=\"M";
    for (std::size_t i = b; i < e; ++i) {
      if (i > b) out += " L";
      point(out, m, plot.points[i]);
    }
    out += "\"/>\n";
  }
  for (std::size_t k = 0; k < plot.pieces.size(); ++k) {
    out += "<path class=\"piece\" data-piece=\"";
    out += std::to_string(k + 1);
    out += "\" stroke=\"";
    out += kPalette[k % kPalette.size()];
    out += "\" d=\"";
    out += piece_d(m, plot.pieces[k].segment);
    out += "\"/>\n";
  }
  for (const Vec2<double>& p : plot.points) {
    out += "<circle class=\"pt\"";
    attrs(out, {{"cx", m.px(p.x)}, {"cy", m.py(p.y)}});
    out += " r=\"1.5\"/>\n";
  }
  out += "</g>\n";
  return height;
}

void deviation_panel(std::string& out, const FitPlot& plot, double top) {
  const std::vector<double> dev = signed_deviations(plot.points, plot.pieces);
  // Distance along the input polyline; paths follow on without the gap.
  std::vector<double> along(plot.points.size(), 0.0);
  double s = 0.0;
  for (const auto& [b, e] : path_ranges(plot))
    for (std::size_t i = b; i < e; ++i) {
      if (i > b) s += distance(plot.points[i - 1], plot.points[i]);
      along[i] = s;
    }
  const double s1 = s > 0 ? s : 1.0;
  double lim = std::fmax(plot.tol_left, plot.tol_right);
  for (const double d : dev)
    if (std::isfinite(d)) lim = std::fmax(lim, std::fabs(d));
  lim = lim > 0 ? lim * 1.15 : 1.0;
  const auto px = [&](double v) { return kLeft + v / s1 * kPlotWidth; };
  const auto py = [&](double v) { return top + kLowerHeight / 2 - v / lim * (kLowerHeight / 2); };

  out += "<g id=\"deviation\">\n";
  frame(out, kLeft, top, kPlotWidth, kLowerHeight);
  axis(out, true, 0.0, s1, px, top + kLowerHeight, top, top + kLowerHeight);
  axis(out, false, -lim, lim, py, kLeft, kLeft, kLeft + kPlotWidth);
  text(out, kLeft + kPlotWidth / 2, top + kLowerHeight + 36, "middle", "distance along the path (mm)");
  std::string rot = " transform=\"rotate(-90 ";
  num_pair(rot, kLeft - 56, " ", top + kLowerHeight / 2);
  rot += ")\"";
  text(out, kLeft - 56, top + kLowerHeight / 2, "middle", "deviation (mm)", rot.c_str());
  for (const double v : {plot.tol_left, -plot.tol_right}) {
    out += "<line class=\"limit\" data-value=\"";
    label(out, v);
    out += '"';
    attrs(out, {{"x1", kLeft}, {"y1", py(v)}, {"x2", kLeft + kPlotWidth}, {"y2", py(v)}});
    out += "/>\n";
  }
  out += "<polyline class=\"dev\" points=\"";
  for (std::size_t i = 0; i < dev.size(); ++i) {
    if (i) out += ' ';
    num_pair(out, px(along[i]), ",", py(dev[i]));  // num() prints a NaN (an uncovered point) as 0
  }
  out += "\"/>\n</g>\n";
}

}  // namespace

std::string format_fit_svg(const FitPlot& plot) {
  const double band = std::fmax(plot.tol_left, plot.tol_right);
  return page(
      ".pt{fill:#333}"
      ".band,.bandkey{fill:none;stroke:#f2d98c;stroke-opacity:0.6;stroke-linecap:round;"
      "stroke-linejoin:round}"
      ".dev{fill:none;stroke:#1f5fb4;stroke-width:1}"
      ".limit{stroke:#d00;stroke-width:1;stroke-dasharray:5 4}",
      plot.title, [&](std::string& out) { legend(out, plot, band); },
      [&](std::string& body) { return xy_panel(body, plot, band); },
      [&](std::string& body, double top) { deviation_panel(body, plot, top); });
}

}  // namespace kerf::io
