#include "io/svg_parts.hpp"

#include <cstdio>
#include <string_view>

// Text is built with += throughout (GCC bug 105329, see fit_output.cpp).

namespace kerf::io::svg {

// A coordinate in px: two decimals are far below a pixel.
void num(std::string& out, double v) {
  if (!std::isfinite(v)) v = 0.0;
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string_view s = buf;
  if (s == "-0.00") s = "0.00";
  out += s;
}

// A tick label: short, no trailing zeros.
void label(std::string& out, double v) {
  if (std::fabs(v) < 1e-9) v = 0.0;
  char buf[40];
  std::snprintf(buf, sizeof buf, "%g", v);
  out += buf;
}

namespace {

// Length of the well-formed UTF-8 sequence at s[i], or 0 (overlongs and
// surrogates are not checked: they are not what a file name holds by mistake).
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2) return 0;
  return n;
}

}  // namespace

// Text for XML: markup escaped; control characters (forbidden in XML 1.0 even
// escaped) and bytes that are not UTF-8 become '?'.
void escaped(std::string& out, const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t n = utf8_length(s, i);
    const char c = s[i];
    if (n > 1) {
      out.append(s, i, n);
      i += n;
      continue;
    }
    ++i;
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += n == 1 && (static_cast<unsigned char>(c) >= 0x20 || c == '\t') ? c : '?';
    }
  }
}

// Swept angle of an arc piece in (0, 2*pi]: start == end is a full turn.
double sweep_angle(const Segment<double>& s) {
  const Vec2<double> a = s.start - s.centre;
  const Vec2<double> b = s.end - s.centre;
  double t = std::atan2(a.cross(b), a.dot(b));  // CCW turn from a to b, in (-pi, pi]
  if (s.dir < 0) t = -t;
  if (t <= 0) t += 2 * kPi;
  return t;
}

void add_arc_points(Box& box, const Segment<double>& s) {
  const Vec2<double> a = s.start - s.centre;
  const double r = a.norm();
  const double a0 = std::atan2(a.y, a.x);
  const double sweep = sweep_angle(s) * (s.dir < 0 ? -1 : 1);
  constexpr int kSteps = 64;
  for (int i = 0; i <= kSteps; ++i) {
    const double t = a0 + sweep * i / kSteps;
    box.add({s.centre.x + r * std::cos(t), s.centre.y + r * std::sin(t)});
  }
}

void point(std::string& out, const XyMap& m, Vec2<double> p) { num_pair(out, m.px(p.x), " ", m.py(p.y)); }

// One piece's path data. SVG's sweep-flag 1 is its positive angle direction,
// which on a y-down screen is clockwise as seen; with y flipped the picture
// looks like the world, so a CCW piece (E = +1) has sweep-flag 0.
std::string piece_d(const XyMap& m, const Segment<double>& s) {
  std::string d = "M";
  point(d, m, s.start);
  // An arc that bends less than a pixel over the whole canvas is drawn as its
  // chord: renderers lose precision with radii of millions of px.
  const bool flat = s.radius() * m.scale > 1e6 && s.start != s.end && sweep_angle(s) < kPi;
  if (!s.is_arc() || flat) {
    d += " L";
    point(d, m, s.end);
    return d;
  }
  std::string r;
  num(r, s.radius() * m.scale);
  const char* sweep_flag = s.dir > 0 ? " 0 " : " 1 ";
  const auto arc = [&](bool large, Vec2<double> to) {
    d += " A";
    d += r;
    d += ' ';
    d += r;
    d += " 0 ";
    d += large ? '1' : '0';
    d += sweep_flag;
    point(d, m, to);
  };
  if (s.start == s.end) {  // a full circle: SVG draws nothing between equal ends
    arc(false, s.centre * 2.0 - s.start);
    arc(false, s.end);
  } else {
    arc(sweep_angle(s) > kPi, s.end);
  }
  return d;
}

// A tick step of 1, 2 or 5 times a power of ten, giving about `target` ticks.
double nice_step(double range, int target) {
  const double raw = range / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * mag;
}

void frame(std::string& out, double x, double y, double w, double h) {
  out += "<rect class=\"frame\"";
  attrs(out, {{"x", x}, {"y", y}, {"width", w}, {"height", h}});
  out += "/>\n";
}

void text(std::string& out, double x, double y, const char* anchor, const std::string& s,
          const char* extra) {
  out += "<text class=\"axis\" text-anchor=\"";
  out += anchor;
  out += '"';
  attrs(out, {{"x", x}, {"y", y}});
  out += extra;
  out += '>';
  escaped(out, s);
  out += "</text>\n";
}

XyPanel xy_panel_frame(std::string& out, Box box, double min_pad, double left, double top,
                       double max_w, double max_h) {
  if (box.empty()) box = {0, 0, 1, 1};
  double dx = box.x1 - box.x0, dy = box.y1 - box.y0;
  const double pad = std::fmax(0.03 * std::fmax(std::fmax(dx, dy), 1e-9), min_pad);
  box.x0 -= pad;
  box.x1 += pad;
  box.y0 -= pad;
  box.y1 += pad;
  dx = box.x1 - box.x0;
  dy = box.y1 - box.y0;
  const double scale = std::fmin(max_w / dx, max_h / dy);
  const XyPanel p{{box.x0, box.y1, scale, left, top}, dx * scale, dy * scale};
  const XyMap& m = p.map;

  out += "<g id=\"xy\">\n";
  frame(out, left, top, p.width, p.height);
  axis(out, true, box.x0, box.x1, [&](double v) { return m.px(v); }, top + p.height, top,
       top + p.height);
  axis(out, false, box.y0, box.y1, [&](double v) { return m.py(v); }, left, left, left + p.width);
  text(out, left + p.width / 2, top + p.height + 36, "middle", "x (mm)");
  std::string rot = " transform=\"rotate(-90 ";
  num_pair(rot, left - 56, " ", top + p.height / 2);
  rot += ")\"";
  text(out, left - 56, top + p.height / 2, "middle", "y (mm)", rot.c_str());
  return p;
}

void open_document(std::string& out, double width, double height, const char* extra_style,
                   const std::string& title, double x, double y) {
  out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\"";
  attrs(out, {{"width", width}, {"height", height}});
  out += " viewBox=\"0 0 ";
  num_pair(out, width, " ", height);
  out += "\" font-family=\"sans-serif\">\n";
  out += "<style>"
         ".frame{fill:none;stroke:#444;stroke-width:1}"
         ".grid{stroke:#e4e4e4;stroke-width:1}"
         ".tick{font-size:11px;fill:#333}"
         ".axis{font-size:13px;fill:#111}"
         ".title{font-size:16px;font-weight:bold;fill:#111}"
         ".piece{fill:none;stroke-width:2}";
  out += extra_style;
  out += "</style>\n";
  out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  out += "<text class=\"title\"";
  attrs(out, {{"x", x}, {"y", y}});
  out += ">";
  escaped(out, title);
  out += "</text>\n";
}

void num_pair(std::string& out, double a, const char* between, double b) {
  num(out, a);
  out += between;
  num(out, b);
}

void attrs(std::string& out, std::initializer_list<Attr> list) {
  for (const Attr& a : list) {
    out += ' ';
    out += a.name;
    out += "=\"";
    num(out, a.value);
    out += '"';
  }
}

void Legend::item(const std::string& swatch, const std::string& name) {
  out += "<g transform=\"translate(";
  num_pair(out, x, " ", y);
  out += ")\">";
  out += swatch;
  out += "<text class=\"tick\" x=\"26\" y=\"4\">";
  escaped(out, name);
  out += "</text></g>\n";
  x += 30 + 7.0 * static_cast<double>(name.size());
}

}  // namespace kerf::io::svg
