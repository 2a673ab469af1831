// Pieces of the SVG plots (`kerf sim --plot`, `kerf fit --format svg`):
// number and text formatting, the XY mapping, a fitted piece as path data,
// axes with ticks and grid, frames and labels.
#pragma once

#include <array>
#include <cmath>
#include <initializer_list>
#include <string>

#include "kerf/geom/segment.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::io::svg {

inline constexpr double kPi = 3.14159265358979323846;

// The page both plots share, in px: the title and a legend row, the XY
// panel at kTopY, and a lower panel kPanelGap below it.
inline constexpr double kWidth = 960;
inline constexpr double kLeft = 80;  // room for the y tick labels
inline constexpr double kRight = 20;
inline constexpr double kPlotWidth = kWidth - kLeft - kRight;
inline constexpr double kTitleY = 24;
inline constexpr double kLegendY = 46;
inline constexpr double kTopY = 70;
inline constexpr double kMaxTopHeight = 560;
inline constexpr double kPanelGap = 70;  // room for the x tick labels and axis title
inline constexpr double kLowerHeight = 200;
inline constexpr double kBottomMargin = 50;

// Piece colours, cycled.
inline constexpr std::array<const char*, 8> kPalette = {
    "#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#bcbd22"};

// A coordinate in px with two decimals (far below a pixel); never "-0.00".
void num(std::string& out, double v);
// A tick label: short, no trailing zeros.
void label(std::string& out, double v);
// Text for XML: markup escaped, control characters and non-UTF-8 bytes as '?'.
void escaped(std::string& out, const std::string& s);

// a, then `between`, then b, the numbers as num() writes them.
void num_pair(std::string& out, double a, const char* between, double b);

// Numeric attributes, each written ` name="value"` (the value as num() writes it).
struct Attr {
  const char* name;
  double value;
};
void attrs(std::string& out, std::initializer_list<Attr> list);

struct Box {
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;  // HUGE_VAL: double (clang warns on INFINITY, a float)
  void add(Vec2<double> p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    x0 = std::fmin(x0, p.x);
    y0 = std::fmin(y0, p.y);
    x1 = std::fmax(x1, p.x);
    y1 = std::fmax(y1, p.y);
  }
  bool empty() const { return !(x0 <= x1); }
};

// World (mm, y up) to px (y down) for the XY panel.
struct XyMap {
  double x0, y1, scale, left, top;
  double px(double x) const { return left + (x - x0) * scale; }
  double py(double y) const { return top + (y1 - y) * scale; }
};

// Swept angle of an arc piece in (0, 2*pi]: start == end is a full turn.
double sweep_angle(const Segment<double>& s);
// Adds points along an arc piece to the box (its bulge, not just its ends).
void add_arc_points(Box& box, const Segment<double>& s);
// "x y" in px.
void point(std::string& out, const XyMap& m, Vec2<double> p);
// One piece's path data ("M.. A.." or "M.. L..").
std::string piece_d(const XyMap& m, const Segment<double>& s);

// A tick step of 1, 2 or 5 times a power of ten, giving about `target` ticks.
double nice_step(double range, int target);

// Ticks and grid lines along one axis of a panel; `to_px` maps a value.
template <class ToPx>
void axis(std::string& out, bool horizontal, double lo, double hi, ToPx to_px, double x_or_y,
          double grid_from, double grid_to) {
  if (!(hi > lo)) return;
  const double step = nice_step(hi - lo, horizontal ? 10 : 6);
  for (double v = std::ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) {
    const double p = to_px(v);
    out += "<line class=\"grid\"";
    if (horizontal)
      attrs(out, {{"x1", p}, {"y1", grid_from}, {"x2", p}, {"y2", grid_to}});
    else
      attrs(out, {{"x1", grid_from}, {"y1", p}, {"x2", grid_to}, {"y2", p}});
    out += horizontal ? "/><text class=\"tick\" text-anchor=\"middle\"" : "/><text class=\"tick\" text-anchor=\"end\"";
    attrs(out, {{"x", horizontal ? p : x_or_y - 6}, {"y", horizontal ? x_or_y + 16 : p + 4}});
    out += ">";
    label(out, v);
    out += "</text>\n";
  }
}

// The document's opening: the XML and <svg> header, the style rules both
// plots share plus `extra_style`, a white background and the title at
// (x, y). The caller appends the panels and "</svg>".
void open_document(std::string& out, double width, double height, const char* extra_style,
                   const std::string& title, double x, double y);
void frame(std::string& out, double x, double y, double w, double h);

// A whole page (see kTopY): `legend(out)` draws the legend row, `xy(body)`
// the XY panel, returning its height, and `lower(body, top)` the lower panel.
template <class DrawLegend, class DrawXy, class DrawLower>
std::string page(const char* extra_style, const std::string& title, DrawLegend legend, DrawXy xy,
                 DrawLower lower) {
  std::string body;
  const double lower_top = kTopY + xy(body) + kPanelGap;
  lower(body, lower_top);
  std::string out;
  open_document(out, kWidth, lower_top + kLowerHeight + kBottomMargin, extra_style, title, kLeft, kTitleY);
  legend(out);
  out += body;
  out += "</svg>\n";
  return out;
}
// The XY panel's opening: `<g id="xy">`, its frame, axes and labels, for
// `box` padded by 3% of its size or `min_pad`, whichever is more, scaled to
// fit max_w x max_h px at (left, top). The caller draws into it and closes
// the group.
struct XyPanel {
  XyMap map;
  double width;
  double height;
};
XyPanel xy_panel_frame(std::string& out, Box box, double min_pad, double left, double top,
                       double max_w, double max_h);

void text(std::string& out, double x, double y, const char* anchor, const std::string& s,
          const char* extra = "");

// A row of legend entries, left to right from (x, y), each a swatch (SVG
// drawn around its own origin) and its name.
struct Legend {
  std::string& out;
  double x;
  double y;
  void item(const std::string& swatch, const std::string& name);
};

}  // namespace kerf::io::svg
