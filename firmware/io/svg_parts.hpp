// Pieces of the SVG plots (`kerf sim --plot`, `kerf fit --format svg`):
// number and text formatting, the XY mapping, a fitted piece as path data,
// axes with ticks and grid, frames and labels.
#pragma once

#include <array>
#include <cmath>
#include <string>

#include "kerf/geom/segment.hpp"
#include "kerf/geom/vec2.hpp"

namespace kerf::io::svg {

inline constexpr double kPi = 3.14159265358979323846;

// Piece colours, cycled.
inline constexpr std::array<const char*, 8> kPalette = {
    "#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#bcbd22"};

// A coordinate in px with two decimals (far below a pixel); never "-0.00".
void num(std::string& out, double v);
// A tick label: short, no trailing zeros.
void label(std::string& out, double v);
// Text for XML: markup escaped, control characters and non-UTF-8 bytes as '?'.
void escaped(std::string& out, const std::string& s);

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
    if (horizontal) {
      out += "<line class=\"grid\" x1=\"";
      num(out, p);
      out += "\" y1=\"";
      num(out, grid_from);
      out += "\" x2=\"";
      num(out, p);
      out += "\" y2=\"";
      num(out, grid_to);
      out += "\"/><text class=\"tick\" text-anchor=\"middle\" x=\"";
      num(out, p);
      out += "\" y=\"";
      num(out, x_or_y + 16);
      out += "\">";
    } else {
      out += "<line class=\"grid\" x1=\"";
      num(out, grid_from);
      out += "\" y1=\"";
      num(out, p);
      out += "\" x2=\"";
      num(out, grid_to);
      out += "\" y2=\"";
      num(out, p);
      out += "\"/><text class=\"tick\" text-anchor=\"end\" x=\"";
      num(out, x_or_y - 6);
      out += "\" y=\"";
      num(out, p + 4);
      out += "\">";
    }
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

}  // namespace kerf::io::svg
