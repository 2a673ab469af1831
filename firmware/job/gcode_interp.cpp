#include "job/gcode_interp.hpp"
#include "job/gcode_flow.hpp"
#include "job/block_interp.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace kerf::job {

const char* to_string(CanonKind k) {
  switch (k) {
    case CanonKind::traverse: return "TRAVERSE";
    case CanonKind::feed: return "FEED";
    case CanonKind::arc: return "ARC";
    case CanonKind::dwell: return "DWELL";
    case CanonKind::pause: return "PAUSE";
    case CanonKind::end: return "END";
    case CanonKind::torch: return "TORCH";
    case CanonKind::digital_out: return "DIGITAL_OUT";
    case CanonKind::analog_out: return "ANALOG_OUT";
    case CanonKind::wait_input: return "WAIT_INPUT";
    case CanonKind::tool: return "TOOL";
    case CanonKind::feed_percent: return "FEED_PERCENT";
    case CanonKind::tolerance: return "TOLERANCE";
  }
  return "?";
}

namespace {

// `pre` then v: "%.4f" (a value), or "%d". Built in one piece: GCC 12
// warns (-Wrestrict) on a literal + std::string here.
std::string num(double v, const char* pre = "") {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%s%.4f", pre, std::fabs(v) < 5e-5 ? 0.0 : v);
  return buf;
}
std::string integer(long long v, const char* pre) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%s%lld", pre, v);
  return buf;
}

}  // namespace

bool interpret(const GcodeFile& g, const InterpSettings& settings, const MachineState& state, Interpretation& out,
               std::string& error) {
  out = Interpretation{};
  if (!g.ok) {
    error = describe_error(g);
    return false;
  }
  error.clear();
  BlockInterp it(settings, state, out);
  GcodeFlow flow(g, [&](std::string_view pin, double& v, std::string& why) {
    return qtplasmac_pin(pin, it.hal_cut_feed(), v, why);
  }, settings.max_blocks, out.constructs, out.notes);
  if (!flow.prepare(error)) return false;
  const GBlock* b = nullptr;
  std::span<const GWord> words;
  std::string why;
  while (flow.next(b, words, error)) {
    if (!it.run(b->line, words, why)) {
      error = where(g.file, b->line) + why;
      return false;
    }
    if (it.ended()) break;
  }
  return error.empty();
}

std::string format_canon(const Interpretation& it) {
  std::string s;
  for (const Canon& c : it.canon) {
    s += std::to_string(c.line);
    s += ' ';
    s += to_string(c.kind);
    switch (c.kind) {
      case CanonKind::traverse:
      case CanonKind::feed:
        s += num(c.end[0], " ") + num(c.end[1], " ") + num(c.end[2], " ");
        if (c.kind == CanonKind::feed) s += num(c.feed_mm_min, " F");
        break;
      case CanonKind::arc:
        s += c.ccw ? " ccw" : " cw";
        s += num(c.end[0], " ") + num(c.end[1], " ") + num(c.end[2], " ") + num(c.centre[0], " centre ") +
             num(c.centre[1], " ") + num(c.feed_mm_min, " F");
        break;
      case CanonKind::dwell:
      case CanonKind::feed_percent:
      case CanonKind::tolerance: s += num(c.value, " "); break;
      case CanonKind::pause: s += c.index == 0 ? " M0" : " M1"; break;
      case CanonKind::end: break;
      case CanonKind::torch: s += integer(c.index, " "); break;
      case CanonKind::tool:
        s += integer(c.index, " ");
        if (c.value >= 0) s += num(c.value, " pierce ");
        break;
      case CanonKind::digital_out:
      case CanonKind::analog_out:
        s += integer(c.index, " ") + num(c.value, " ");
        s += c.sync ? " sync" : " now";
        break;
      case CanonKind::wait_input:
        s += integer(c.index, " ") + integer(c.mode, " L") + num(c.value, " ");
        break;
    }
    s += '\n';
  }
  for (const std::string& n : it.notes) {
    s += "NOTE ";
    s += n;
    s += '\n';
  }
  const MachineState& st = it.state;
  s += "STATE coord ";
  s += coord_name(st.coord);
  for (int k = 0; k < kCoordSystems; ++k)
    if (st.g5x[k][0] != 0 || st.g5x[k][1] != 0 || st.g5x[k][2] != 0) {
      s += ' ';
      s += coord_name(k);
      s += num(st.g5x[k][0], " ") + num(st.g5x[k][1], " ") + num(st.g5x[k][2], " ");
    }
  if (st.g92_on) s += num(st.g92[0], " G92 ") + num(st.g92[1], " ") + num(st.g92[2], " ");
  s += '\n';
  return s;
}

}  // namespace kerf::job
