#include "io/run_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/svg_parts.hpp"

// Text is built with += throughout (GCC bug 105329, see fit_output.cpp).

namespace kerf::io {

namespace {

using namespace svg;

// Indices in [begin, end) to draw, at most kMaxPolylineVertices: per bucket
// its first and last and, for each of the `nkeys` keys, its lowest and highest.
template <class Key>
std::vector<std::size_t> decimate(std::size_t begin, std::size_t end, std::size_t nkeys, Key key) {
  std::vector<std::size_t> keep;
  const std::size_t n = end - begin;
  if (n <= kMaxPolylineVertices) {
    for (std::size_t i = begin; i < end; ++i) keep.push_back(i);
    return keep;
  }
  const std::size_t per_bucket = 2 + 2 * nkeys;
  const std::size_t buckets = kMaxPolylineVertices / per_bucket;
  const std::size_t size = (n + buckets - 1) / buckets;
  std::vector<std::size_t> picks;
  for (std::size_t b = begin; b < end; b += size) {
    const std::size_t e = std::min(end, b + size);
    picks.assign({b, e - 1});
    for (std::size_t k = 0; k < nkeys; ++k) {
      std::size_t lo = b, hi = b;
      for (std::size_t i = b; i < e; ++i) {
        if (key(i, k) < key(lo, k)) lo = i;
        if (key(i, k) > key(hi, k)) hi = i;
      }
      picks.push_back(lo);
      picks.push_back(hi);
    }
    std::sort(picks.begin(), picks.end());
    picks.erase(std::unique(picks.begin(), picks.end()), picks.end());
    keep.insert(keep.end(), picks.begin(), picks.end());
  }
  return keep;
}

// Maximal runs of equal torch state: [begin, end) sample ranges.
struct Run {
  std::size_t begin, end;
  bool torch;
};

std::vector<Run> torch_runs(const std::vector<TraceSample>& trace) {
  std::vector<Run> runs;
  for (std::size_t i = 0; i < trace.size(); ++i) {
    if (runs.empty() || runs.back().torch != trace[i].torch) runs.push_back({i, i + 1, trace[i].torch});
    else runs.back().end = i + 1;
  }
  return runs;
}

void legend(std::string& out, const RunPlot& plot) {
  Legend row{out, kLeft, kLegendY};
  const auto item = [&](const std::string& swatch, const std::string& name) { row.item(swatch, name); };
  item("<circle class=\"pt\" cx=\"10\" cy=\"0\" r=\"2\"/>", "input points");
  item("<line x1=\"0\" y1=\"0\" x2=\"20\" y2=\"0\" stroke=\"#1f77b4\" stroke-width=\"2\"/>",
       "fitted pieces (" + std::to_string(plot.pieces.size()) + ")");
  if (plot.tol > 0) {
    std::string name = "band \u00b1";
    label(name, plot.tol);
    name += " mm";
    item("<line class=\"band\" x1=\"0\" y1=\"0\" x2=\"20\" y2=\"0\" stroke-width=\"8\"/>", name);
  }
  item("<line class=\"cut\" x1=\"0\" y1=\"0\" x2=\"20\" y2=\"0\"/>", "cut (torch on)");
  item("<line class=\"rapid\" x1=\"0\" y1=\"0\" x2=\"20\" y2=\"0\"/>", "rapid (torch off)");
  item("<circle class=\"pierce\" cx=\"10\" cy=\"0\" r=\"4\"/>", "pierce");
  if (!plot.marks.empty()) {
    item("<rect class=\"dwell\" x=\"6\" y=\"-4\" width=\"8\" height=\"8\"/>", "dwell");
    item("<rect class=\"pause\" x=\"6\" y=\"-4\" width=\"8\" height=\"8\" transform=\"rotate(45 10 0)\"/>",
         "pause");
  }
  if (plot.table) item("<rect class=\"table\" x=\"0\" y=\"-6\" width=\"20\" height=\"12\"/>", "table (soft limits)");
  item("<rect class=\"on\" x=\"0\" y=\"-6\" width=\"20\" height=\"12\"/>", "torch on (speed)");
}

void polyline(std::string& out, const char* cls, const std::vector<std::size_t>& idx,
              const std::vector<TraceSample>& trace, const XyMap& m) {
  out += "<polyline class=\"";
  out += cls;
  out += "\" points=\"";
  for (std::size_t k = 0; k < idx.size(); ++k) {
    if (k) out += ' ';
    num_pair(out, m.px(trace[idx[k]].pos.x), ",", m.py(trace[idx[k]].pos.y));
  }
  out += "\"/>\n";
}

// The XY panel; returns its height in px.
double xy_panel(std::string& out, const RunPlot& plot, const std::vector<Run>& runs) {
  Box box;
  for (const auto& path : plot.paths)
    for (const Vec2<double>& p : path) box.add(p);
  for (const Segment<double>& s : plot.pieces) {
    box.add(s.start);
    box.add(s.end);
    if (s.is_arc()) add_arc_points(box, s);
  }
  for (const TraceSample& t : plot.trace) box.add(t.pos);
  if (plot.table) {
    box.add(plot.table_lo);
    box.add(plot.table_hi);
  }
  const XyPanel panel = xy_panel_frame(out, box, 0.0, kLeft, kTopY, kPlotWidth, kMaxTopHeight);
  const XyMap& m = panel.map;
  const double scale = m.scale;
  const double height = panel.height;

  if (plot.table) {
    out += "<rect class=\"table\"";
    attrs(out, {{"x", m.px(plot.table_lo.x)}, {"y", m.py(plot.table_hi.y)},
                {"width", (plot.table_hi.x - plot.table_lo.x) * scale},
                {"height", (plot.table_hi.y - plot.table_lo.y) * scale}});
    out += "/>\n";
  }
  // The band under the pieces, when it is wide enough to see.
  const double band_px = 2 * plot.tol * scale;
  std::vector<std::string> ds;
  for (const Segment<double>& s : plot.pieces) ds.push_back(piece_d(m, s));
  if (band_px >= 0.5) {
    out += "<g class=\"band\" stroke-width=\"";
    num(out, band_px);
    out += "\">\n";
    for (const std::string& d : ds) {
      out += "<path d=\"";
      out += d;
      out += "\"/>\n";
    }
    out += "</g>\n";
  }
  for (std::size_t i = 0; i < ds.size(); ++i) {
    out += "<path class=\"piece\" data-path=\"";
    out += std::to_string(i < plot.piece_path.size() ? plot.piece_path[i] : 0);
    out += "\" stroke=\"";
    out += kPalette[i % kPalette.size()];
    out += "\" d=\"";
    out += ds[i];
    out += "\"/>\n";
  }
  // Each run starts at the previous run's last sample, so the drawing is unbroken.
  const auto& tr = plot.trace;
  for (const Run& r : runs) {
    const std::size_t from = r.begin > 0 ? r.begin - 1 : r.begin;
    const auto idx = decimate(from, r.end, 2, [&](std::size_t i, std::size_t k) {
      return k == 0 ? tr[i].pos.x : tr[i].pos.y;
    });
    polyline(out, r.torch ? "cut" : "rapid", idx, tr, m);
  }
  // The points over the trace, so that both stay visible.
  for (const auto& path : plot.paths)
    for (const Vec2<double>& p : path) {
      out += "<circle class=\"pt\"";
      attrs(out, {{"cx", m.px(p.x)}, {"cy", m.py(p.y)}});
      out += " r=\"1.2\"/>\n";
    }
  for (const Run& r : runs) {
    if (!r.torch) continue;
    out += "<circle class=\"pierce\"";
    attrs(out, {{"cx", m.px(tr[r.begin].pos.x)}, {"cy", m.py(tr[r.begin].pos.y)}});
    out += " r=\"4\"/>\n";
  }
  for (const PlotMark& k : plot.marks) {  // a square for a dwell, the same turned 45 degrees for a pause
    const double x = m.px(k.at.x), y = m.py(k.at.y);
    out += "<rect class=\"" + k.kind + "\"";
    attrs(out, {{"x", x - 4}, {"y", y - 4}});
    out += " width=\"8\" height=\"8\"";
    if (k.kind == "pause") {
      out += " transform=\"rotate(45 ";
      num_pair(out, x, " ", y);
      out += ")\"";
    }
    out += "><title>";
    for (const char c : k.text) out += c == '<' ? std::string("&lt;") : c == '&' ? std::string("&amp;") : std::string(1, c);
    out += "</title></rect>\n";
  }
  out += "</g>\n";
  return height;
}

void speed_panel(std::string& out, const std::vector<TraceSample>& tr, const std::vector<Run>& runs,
                 double top) {
  // Speed at each sample from the step before it.
  std::vector<double> ts, vs;
  for (std::size_t i = 1; i < tr.size(); ++i) {
    const double dt = tr[i].t_s - tr[i - 1].t_s;
    if (!(dt > 0)) continue;
    ts.push_back(tr[i].t_s);
    vs.push_back(distance(tr[i - 1].pos, tr[i].pos) / dt * 60.0);
  }
  double t0 = 0, t1 = 1;
  if (!tr.empty() && tr.back().t_s > tr.front().t_s) {
    t0 = tr.front().t_s;
    t1 = tr.back().t_s;
  }
  double vmax = 0;
  for (const double v : vs) vmax = std::fmax(vmax, v);
  vmax = vmax > 0 ? vmax * 1.05 : 1.0;
  const auto px = [&](double t) { return kLeft + (t - t0) / (t1 - t0) * kPlotWidth; };
  const auto py = [&](double v) { return top + kLowerHeight - v / vmax * kLowerHeight; };

  out += "<g id=\"speed\">\n";
  for (const Run& r : runs) {
    if (!r.torch) continue;
    const double a = tr[r.begin].t_s;
    const double b = r.end < tr.size() ? tr[r.end].t_s : tr[r.end - 1].t_s;
    out += "<rect class=\"on\"";
    attrs(out, {{"x", px(a)}, {"y", top}, {"width", std::fmax(px(b) - px(a), 0.5)}, {"height", kLowerHeight}});
    out += "/>\n";
  }
  frame(out, kLeft, top, kPlotWidth, kLowerHeight);
  axis(out, true, t0, t1, px, top + kLowerHeight, top, top + kLowerHeight);
  axis(out, false, 0.0, vmax, py, kLeft, kLeft, kLeft + kPlotWidth);
  text(out, kLeft + kPlotWidth / 2, top + kLowerHeight + 36, "middle", "t (s)");
  std::string rot = " transform=\"rotate(-90 ";
  num_pair(rot, kLeft - 56, " ", top + kLowerHeight / 2);
  rot += ")\"";
  text(out, kLeft - 56, top + kLowerHeight / 2, "middle", "speed (mm/min)", rot.c_str());
  if (vs.empty()) {
    text(out, kLeft + kPlotWidth / 2, top + kLowerHeight / 2, "middle", "no trace");
  } else {
    const auto idx = decimate(0, vs.size(), 1, [&](std::size_t i, std::size_t) { return vs[i]; });
    out += "<polyline class=\"speed\" points=\"";
    for (std::size_t k = 0; k < idx.size(); ++k) {
      if (k) out += ' ';
      num_pair(out, px(ts[idx[k]]), ",", py(vs[idx[k]]));
    }
    out += "\"/>\n";
  }
  out += "</g>\n";
}

}  // namespace

std::string format_run_svg(const RunPlot& plot) {
  const std::vector<Run> runs = torch_runs(plot.trace);
  return page(
      ".pt{fill:#555}"
      ".band,.band path{fill:none;stroke:#f2d98c;stroke-opacity:0.6;stroke-linecap:round}"
      ".cut{fill:none;stroke:#222;stroke-width:0.75}"
      ".rapid{fill:none;stroke:#999;stroke-width:1;stroke-dasharray:5 4}"
      ".pierce{fill:none;stroke:#d00;stroke-width:1.5}"
      ".on{fill:#ffe0b0;stroke:none}"
      ".dwell{fill:#1f77b4;fill-opacity:0.7;stroke:#124}"
      ".pause{fill:#ff9f1c;fill-opacity:0.8;stroke:#840}"
      ".speed{fill:none;stroke:#1f5fb4;stroke-width:1}"
      ".table{fill:none;stroke:#2a2;stroke-width:1.5}",
      plot.title, [&](std::string& out) { legend(out, plot); },
      [&](std::string& body) { return xy_panel(body, plot, runs); },
      [&](std::string& body, double top) { speed_panel(body, plot.trace, runs, top); });
}

}  // namespace kerf::io
