#include "control/run_report.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace kerf::control {

RunSummary summarise_run(const RunReport& r, std::size_t paths, const std::string& link, bool resumed,
                         const Journal* journal) {
  RunSummary s;
  s.state = to_string(r.state);
  s.reason = r.reason;
  s.link = link;
  s.paths = paths;
  s.pierces = r.pierces;
  s.z_moves = r.z_moves;
  s.final_z = r.final_z;
  s.planned = r.planned;
  s.executed = r.completed_this_run;
  s.last_executed = r.last_completed + 1;
  s.resumed_from = resumed ? r.first + 1 : 0;
  s.has_cut_to = r.has_cut_to;
  s.cut_to = r.cut_to;
  s.torch_off_valid = r.torch_off_valid;
  s.torch_off_at = r.torch_off_at;
  s.stopped_at = r.stopped_at;
  s.link_errors = r.link_errors;
  s.executed_total = journal ? journal->state().executed_total : r.completed_this_run;
  s.duplicates = journal ? journal->state().duplicates : 0;
  s.runs = journal ? journal->state().runs : 1;
  s.resets = r.resets;
  s.reset_refused = r.reset_refused;
  s.max_ferror_mm = r.max_ferror_mm;
  s.ferror_at_fault_mm = r.ferror_at_fault_mm;
  s.ferror_limit_mm = r.ferror_limit_mm;
  s.actions = r.action_counts.run;
  s.dwells = r.action_counts.dwells;
  s.pauses = r.action_counts.pauses;
  return s;
}

namespace {

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", static_cast<unsigned>(c));
      out += esc;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string point(Vec2<double> p) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "[%.6f, %.6f]", p.x, p.y);
  return buf;
}

}  // namespace

std::string format_run_json(const RunSummary& s) {
  std::string cut_to = "null";
  if (s.has_cut_to)
    cut_to = "{\"segment\": " + std::to_string(s.cut_to.segment + 1) + ", \"at\": " + point(s.cut_to.at) + "}";
  std::string histogram = "null";
  if (!s.rt_histogram.empty()) {  // "[8, 16) us  4123" lines as a JSON array of strings
    histogram = "[";
    std::size_t from = 0;
    while (from < s.rt_histogram.size()) {
      std::size_t nl = s.rt_histogram.find('\n', from);
      if (nl == std::string::npos) nl = s.rt_histogram.size();
      if (nl > from) histogram += (histogram.size() > 1 ? ", " : "") + json_string(s.rt_histogram.substr(from, nl - from));
      from = nl + 1;
    }
    histogram += "]";
  }
  std::string program;  // a G-code program's constructs, dry run and notes
  if (s.gcode) {
    program = "  \"dry_run\": " + std::string(s.dry_run ? "true" : "false") + ",\n  \"dwells\": " +
              std::to_string(s.dwells) + ",\n  \"pauses\": " + std::to_string(s.pauses) + ",\n  \"actions\": " +
              std::to_string(s.actions) + ",\n  \"constructs\": [";
    for (std::size_t i = 0; i < s.constructs.size(); ++i) {
      const ConstructUse& c = s.constructs[i];
      program += std::string(i ? ", " : "") + "{\"name\": " + json_string(c.name) + ", \"handling\": \"" +
                 c.handling + "\", \"count\": " + std::to_string(c.count) +
                 ", \"first_line\": " + std::to_string(c.first_line) + "}";
    }
    program += "],\n  \"notes\": [";
    for (std::size_t i = 0; i < s.notes.size(); ++i) program += (i ? ", " : "") + json_string(s.notes[i]);
    program += "],\n";
  }
  char buf[4096];
  std::snprintf(
      buf, sizeof buf,
      "{\n  \"state\": \"%s\",\n  \"fault\": %s,\n  \"link\": \"%s\",\n  \"paths\": %zu,\n  \"pierces\": %zu,\n"
      "  \"segments_planned\": %zu,\n  \"segments_executed\": %zu,\n  \"segments_executed_total\": %llu,\n"
      "  \"duplicates\": %llu,\n  \"last_executed_segment\": %lld,\n  \"resumed_from_segment\": %zu,\n"
      "  \"runs\": %u,\n  \"cut_to\": %s,\n  \"torch_on\": %s,\n  \"torch_off_at\": %s,\n  \"stopped_at\": %s,\n"
      "  \"link_errors\": %llu,\n  \"board_duplicates_dropped\": %u,\n  \"max_path_deviation_mm\": %.6f,\n"
      "  \"duration_s\": %.6f,\n  \"wall_s\": %.3f,\n  \"rt\": %s,\n  \"rt_histogram\": %s\n}\n",
      s.state.c_str(), s.reason.empty() ? "null" : json_string(s.reason).c_str(), s.link.c_str(), s.paths,
      s.pierces, s.planned, s.executed, static_cast<unsigned long long>(s.executed_total),
      static_cast<unsigned long long>(s.duplicates), static_cast<long long>(s.last_executed), s.resumed_from,
      s.runs, cut_to.c_str(), s.torch_on ? "true" : "false",
      s.torch_off_valid ? point(s.torch_off_at).c_str() : "null", point(s.stopped_at).c_str(),
      static_cast<unsigned long long>(s.link_errors), s.board_duplicates, s.max_path_deviation_mm,
      s.duration_s, s.wall_s, s.rt.empty() ? "null" : json_string(s.rt).c_str(), histogram.c_str());
  std::string out = buf;
  if (!program.empty()) out.insert(out.find("  \"link\":"), program);
  if (s.z_moves > 0) {  // a machine with a z axis
    char z[96];
    std::snprintf(z, sizeof z, "  \"z_moves\": %zu,\n  \"final_z\": %.6f,\n", s.z_moves, s.final_z);
    out.insert(out.find("  \"segments_planned\":"), z);
  }
  out.insert(out.find("  \"link\":"), std::string("  \"dry_run_option\": ") + (s.dry_run_option ? "true" : "false") + ",\n");
  out.insert(out.find("  \"segments_planned\":"), "  \"fit_forced_commits\": " + std::to_string(s.forced_commits) + ",\n");
  char ferror[160];
  std::snprintf(ferror, sizeof ferror, "{\"max_mm\": %.6f, \"at_fault_mm\": %.6f, \"limit_at_fault_mm\": %.6f}",
                s.max_ferror_mm, s.ferror_at_fault_mm, s.ferror_limit_mm);
  out.insert(out.find("  \"link_errors\":"), "  \"resets\": " + std::to_string(s.resets) + ",\n  \"reset_refused\": " +
                                                 (s.reset_refused.empty() ? "null" : json_string(s.reset_refused)) +
                                                 ",\n  \"following_error\": " + ferror + ",\n");
  std::string rules = "  \"cut_rules\": [";
  for (std::size_t i = 0; i < s.cut_rules.size(); ++i) {
    const CutRuleNote& n = s.cut_rules[i];
    char one[200];
    std::snprintf(one, sizeof one, "%s{\"path\": %zu, \"rule\": %s, \"segment\": %zu, \"value_mm\": %.3f, \"feed_percent\": %g}",
                  i ? ", " : "", n.path + 1, json_string(n.rule).c_str(), n.segment + 1, n.value, n.feed_percent);
    rules += one;
  }
  out.insert(out.find("  \"link_errors\":"), rules + "],\n");
  return out;
}

std::string format_run_summary(const RunSummary& s) {
  char head[512], tail[256];
  std::snprintf(head, sizeof head,
                "kerf %s: %s over %s: %zu paths, %zu of %zu segments executed this run (last %lld; "
                "%llu in all, %llu duplicates), %zu pierces",
                s.simulated ? "sim" : "run", s.state.c_str(), s.link.c_str(), s.paths, s.executed, s.planned,
                static_cast<long long>(s.last_executed), static_cast<unsigned long long>(s.executed_total),
                static_cast<unsigned long long>(s.duplicates), s.pierces);
  if (s.z_moves > 0) {
    const std::size_t used = std::strlen(head);
    std::snprintf(head + used, sizeof head - used, ", %zu z moves (final z %.3f mm)", s.z_moves, s.final_z);
  }
  if (s.simulated)
    std::snprintf(tail, sizeof tail, "; max path deviation %.6f mm; %.3f s simulated, %.3f s wall", s.max_path_deviation_mm,
                  s.duration_s, s.wall_s);
  else
    std::snprintf(tail, sizeof tail, "; %.3f s", s.duration_s);
  std::string program;
  if (s.gcode) {
    program = s.dry_run ? "; dry run (no M3/M4 in the program): torch off" : "";
    if (s.actions > 0)
      program += "; " + std::to_string(s.dwells) + " dwells, " + std::to_string(s.pauses) + " pauses, " +
                 std::to_string(s.actions) + " program actions";
  }
  if (s.dry_run_option) program += "; DRY RUN (--dry-run): torch and gas outputs held off";
  if (s.forced_commits > 0)
    program += "; " + std::to_string(s.forced_commits) + " forced commits in the fit's window (more pieces than the fewest)";
  std::string out = std::string(head) + tail + program + "; torch " + (s.torch_on ? "ON" : "off") +
                    (s.reason.empty() ? "" : "; stopped: " + s.reason) + "\n";
  if (!s.cut_rules.empty()) {  // path N rule feed %, ...
    out += std::string("kerf ") + (s.simulated ? "sim" : "run") + ": cut rules:";
    for (std::size_t i = 0; i < s.cut_rules.size(); ++i) {
      char one[96];
      std::snprintf(one, sizeof one, "%s path %zu %s %g %%", i ? "," : "", s.cut_rules[i].path + 1,
                    s.cut_rules[i].rule.c_str(), s.cut_rules[i].feed_percent);
      out += one;
    }
    out += "\n";
  }
  if (s.gcode && !s.constructs.empty()) {  // the constructs seen: NAME handling (count), ...
    out += std::string("kerf ") + (s.simulated ? "sim" : "run") + ": G-code:";
    for (std::size_t i = 0; i < s.constructs.size(); ++i)
      out += (i ? ", " : " ") + s.constructs[i].name + " " + s.constructs[i].handling + " (" +
             std::to_string(s.constructs[i].count) + ")";
    out += "\n";
  }
  return out;
}

}  // namespace kerf::control
