#include "io/sim_output.hpp"

#include <cstdio>

namespace kerf::io {

double max_path_deviation(const std::vector<sim::TraceSample>& trace,
                          const std::vector<fit::Piece<double>>& pieces) {
  double worst = 0.0;
  for (const sim::TraceSample& s : trace) {
    if (s.seq == 0 || s.seq > pieces.size()) continue;
    const double d = distance_to_segment(pieces[s.seq - 1].segment, s.pos);
    if (d > worst) worst = d;
  }
  return worst;
}

SimSummary summarise(const control::SimJobResult& r, const std::vector<fit::Piece<double>>& pieces,
                     const std::string& link) {
  SimSummary s;
  s.state = r.stream.ok ? "done" : "fault";
  s.fault = r.stream.ok ? "" : r.stream.fault;
  s.link = link;
  s.planned = r.stream.planned;
  s.sent = r.stream.sent;
  s.executed = static_cast<std::uint32_t>(r.executed.size());
  s.last_executed = r.board.last_executed;
  s.resent = r.stream.resent;
  s.duplicates = r.board.duplicates;
  s.torch_on = r.board.torch;
  s.max_path_deviation_mm = max_path_deviation(r.trace, pieces);
  s.duration_s = r.sim_s;
  s.wall_s = r.wall_s;
  return s;
}

std::string format_trace_csv(const std::vector<sim::TraceSample>& trace) {
  std::string out = "t_s,x_mm,y_mm,segment,torch\n";
  char line[160];
  for (const sim::TraceSample& s : trace) {
    std::snprintf(line, sizeof line, "%.6f,%.6f,%.6f,%u,%d\n", s.t_s, s.pos.x, s.pos.y,
                  static_cast<unsigned>(s.seq), s.torch ? 1 : 0);
    out += line;
  }
  return out;
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
}  // namespace

std::string format_sim_json(const SimSummary& s) {
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "{\n  \"state\": \"%s\",\n  \"fault\": %s,\n  \"link\": \"%s\",\n"
                "  \"segments_planned\": %u,\n  \"segments_sent\": %u,\n"
                "  \"segments_executed\": %u,\n  \"last_executed_segment\": %u,\n"
                "  \"segments_resent\": %llu,\n  \"duplicates\": %u,\n  \"torch_on\": %s,\n"
                "  \"max_path_deviation_mm\": %.6f,\n  \"duration_s\": %.6f,\n  \"wall_s\": %.3f\n}\n",
                s.state.c_str(), s.fault.empty() ? "null" : json_string(s.fault).c_str(),
                s.link.c_str(), s.planned, s.sent, s.executed, s.last_executed,
                static_cast<unsigned long long>(s.resent), s.duplicates,
                s.torch_on ? "true" : "false", s.max_path_deviation_mm, s.duration_s, s.wall_s);
  return buf;
}

std::string format_sim_summary(const SimSummary& s) {
  char buf[1024];
  std::snprintf(buf, sizeof buf,
                "kerf sim: %s over %s: %u of %u segments executed (last %u), %u sent, %llu resent, "
                "%u duplicates dropped; max path deviation %.6f mm; %.3f s simulated, %.3f s wall; "
                "torch %s%s%s\n",
                s.state.c_str(), s.link.c_str(), s.executed, s.planned, s.last_executed, s.sent,
                static_cast<unsigned long long>(s.resent), s.duplicates, s.max_path_deviation_mm,
                s.duration_s, s.wall_s, s.torch_on ? "ON" : "off",
                s.fault.empty() ? "" : "; fault: ", s.fault.c_str());
  return buf;
}

}  // namespace kerf::io
