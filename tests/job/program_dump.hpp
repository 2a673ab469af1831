// A program stream's items and summary as text, every number as a hex float
// (%a): two dumps are equal only when every point, feed and field is equal
// bit for bit. Shared by the window reading's tests and its probe.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "job/program_stream.hpp"

namespace kerf_test {

inline std::string hex(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

// s += each part: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string&&.
template <class... Parts>
void put(std::string& s, const Parts&... parts) {
  ((s += parts), ...);
}

inline std::string num(std::size_t v) { return std::to_string(v); }

inline std::string dump_moves(const char* when, const std::vector<kerf::job::ProgramMove>& moves) {
  std::string s;
  for (const kerf::job::ProgramMove& m : moves)
    put(s, " ", when, m.z ? " z " : " xy ", hex(m.xy.x), " ", hex(m.xy.y), " ", hex(m.z_end), " ",
        hex(m.feed_mm_min), " line ", num(m.line), "\n");
  return s;
}

inline std::string dump_path(const kerf::job::ProgramPiece& p) {
  const kerf::job::ProgramPath& q = p.path;
  std::string s;
  put(s, "PATH torch ", num(q.torch), " feed ", hex(q.feed_mm_min), " pierce ", hex(q.pierce_delay_s), " tol ",
      hex(q.tol), " points ", num(p.points.size()), " lines ", num(p.lines.size()), " feeds ", num(p.feed.size()),
      "\n");
  s += dump_moves("before", q.before);
  for (std::size_t k = 0; k < p.points.size() && k < p.lines.size() && k < p.feed.size(); ++k)
    put(s, " ", hex(p.points[k].x), " ", hex(p.points[k].y), " ", num(p.lines[k]), " ", hex(p.feed[k]), "\n");
  s += dump_moves("after", q.after);
  return s;
}

inline std::string dump_action(const kerf::job::ProgramAction& a) {
  std::string s;
  put(s, "ACTION ", kerf::job::to_string(a.kind), " before ", num(a.before_path), " line ", num(a.line), " index ",
      std::to_string(a.index), " mode ", std::to_string(a.mode), " value ", hex(a.value), " sync ", num(a.sync),
      " at ", hex(a.at.x), " ", hex(a.at.y), "\n");
  return s;
}

inline std::string dump_summary(const kerf::job::GcodeProgram& p) {
  std::string s;
  put(s, "SUMMARY file ", p.points.file, " dry_run ", num(p.dry_run), " z_moves ", num(p.z_moves), " final_z ",
      hex(p.final_z), " duplicates ", num(p.points.duplicates_dropped), " points ", num(p.points.points.size()),
      " paths ", num(p.paths.size()), " actions ", num(p.actions.size()), "\n");
  for (const auto& [name, c] : p.interp.constructs)
    put(s, " construct ", name, ": ", c.handling, " ", num(c.count), " ", num(c.first_line), "\n");
  for (const std::string& n : p.interp.notes) put(s, " note ", n, "\n");
  for (const auto& [n, line] : p.interp.analog_inputs) put(s, " analog ", std::to_string(n), " ", num(line), "\n");
  const kerf::job::MachineState& st = p.interp.state;
  put(s, " state coord ", std::to_string(st.coord), " g92_on ", num(st.g92_on));
  for (const auto& sys : st.g5x)
    for (const double v : sys) put(s, " ", hex(v));
  for (const double v : st.g92) put(s, " ", hex(v));
  s += "\n";
  return s;
}

// Every item of a stream until its end or error, then the summary or the error.
struct Drained {
  std::vector<std::string> items;
  std::string tail;  // the summary, or "ERROR text"
  bool ok = false;
  std::size_t paths = 0, points = 0, actions = 0;
};

inline Drained drain(kerf::job::ProgramStream& s, bool keep = true) {
  using Next = kerf::job::ProgramStream::Next;
  Drained d;
  kerf::job::ProgramPiece piece;
  kerf::job::ProgramAction action;
  for (;;) {
    const Next n = s.next(piece, action);
    if (n == Next::path) {
      ++d.paths;
      d.points += piece.points.size();
      if (keep) d.items.push_back(dump_path(piece));
    } else if (n == Next::action) {
      ++d.actions;
      if (keep) d.items.push_back(dump_action(action));
    } else if (n == Next::end) {
      d.ok = true;
      d.tail = dump_summary(s.summary());
      return d;
    } else {
      d.tail = "ERROR " + s.error();
      return d;
    }
  }
}

}  // namespace kerf_test
