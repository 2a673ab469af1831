#include "io/fit_gcode.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "io/fit_deviation.hpp"

// Text is built with += throughout (GCC bug 105329, see fit_output.cpp).

namespace kerf::io {

namespace {

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  // "-0.000" is a valid number, but a diff against a hand-written file trips on it.
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

double rounded(double v, int decimals) {
  return std::strtod(fixed(v, decimals).c_str(), nullptr);
}

Vec2<double> rounded(Vec2<double> p, int decimals) {
  return {rounded(p.x, decimals), rounded(p.y, decimals)};
}

// True when piece k starts a new path: it does not start where k-1 ended.
bool starts_path(Span<const fit::Piece<double>> pieces, std::size_t k) {
  return k == 0 || !(pieces[k].segment.start == pieces[k - 1].segment.end);
}

void xy(std::string& out, Vec2<double> p, int d) {
  out += " X";
  out += fixed(p.x, d);
  out += " Y";
  out += fixed(p.y, d);
}

}  // namespace

std::vector<fit::Piece<double>> rounded_pieces(const GcodeFit& g) {
  std::vector<fit::Piece<double>> out(g.pieces.begin(), g.pieces.end());
  const int d = g.decimals;
  Vec2<double> at{};
  for (std::size_t k = 0; k < out.size(); ++k) {
    Segment<double>& s = out[k].segment;
    if (starts_path(g.pieces, k)) at = rounded(s.start, d);
    const Vec2<double> centre = s.centre;
    s.start = at;
    s.end = rounded(s.end, d);
    if (s.is_arc()) s.centre = at + rounded(centre - at, d);
    at = s.end;
  }
  return out;
}

double written_deviation(const GcodeFit& g) {
  const std::vector<fit::Piece<double>> w = rounded_pieces(g);
  const std::vector<double> dev = signed_deviations(g.points, {w.data(), w.size()});
  double widen = 0.0;  // how much the drawn arc's radius drifts from start to end
  for (const fit::Piece<double>& pc : w)
    if (pc.segment.is_arc())
      widen = std::fmax(widen, std::fabs(pc.segment.radius() -
                                         (pc.segment.end - pc.segment.centre).norm()));
  double worst = 0.0;
  for (const double d : dev) worst = std::isnan(d) ? std::numeric_limits<double>::infinity() : std::fmax(worst, std::fabs(d));
  return worst + widen;
}

int gcode_decimals(GcodeFit g, double tol, int lo) {
  for (g.decimals = lo; g.decimals < 12; ++g.decimals)
    if (written_deviation(g) <= tol) return g.decimals;
  return 12;
}

std::string format_fit_gcode(const GcodeFit& g) {
  const std::vector<fit::Piece<double>> w = rounded_pieces(g);
  const int d = g.decimals;
  std::string out = "; ";
  for (const char c : g.comment)  // a line end in a file name would end the comment
    out += static_cast<unsigned char>(c) < 0x20 ? '?' : c;
  out += "\nG21 G90 G17\n";
  char feed[64];
  std::snprintf(feed, sizeof feed, " F%g", g.feed);
  for (std::size_t k = 0; k < w.size(); ++k) {
    const Segment<double>& s = w[k].segment;
    const bool first = starts_path(g.pieces, k);
    if (first) {
      out += "G0";
      xy(out, s.start, d);
      out += '\n';
    }
    if (!s.is_arc()) {
      out += "G1";
      xy(out, s.end, d);
    } else {
      out += s.dir < 0 ? "G2" : "G3";
      xy(out, s.end, d);
      out += " I";
      out += fixed(s.centre.x - s.start.x, d);
      out += " J";
      out += fixed(s.centre.y - s.start.y, d);
    }
    if (first) out += feed;
    out += '\n';
  }
  out += "M2\n";
  return out;
}

}  // namespace kerf::io
