// Checks one `kerf sim` run of a G-code file against the file itself:
//   sim_corpus_check FILE TRACE.csv REPORT.json TOL
// - the report says done, every planned segment executed, none twice;
// - the trace never goes back to an earlier segment (each runs once, in
//   order), and the last one run is the last planned;
// - every torch-on setpoint (in a file with no torch word, a dry run: every
//   setpoint of a cut segment) lies within TOL + kSlack of the file's cut
//   moves, read by the independent reader (tests/support/toolpath_reader.hpp).
// kSlack: the arc sampling of the job reader (0.001 mm), the link's 1 um grid
// (segment_contract.hpp: up to 3 um for arcs of a few um radius) and the
// drives' counts (0.5 um). Prints the figures; exit 1 on a failed check.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "toolpath_reader.hpp"

namespace {

constexpr double kSlack = 0.005;

bool read_file(const std::string& path, std::string& out) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::stringstream ss;
  ss << f.rdbuf();
  out = ss.str();
  return true;
}

// A top-level "key": value of the report (a number, a string or null).
// (No std::regex: GCC 12 warns inside <regex> under the sanitizers.)
std::string json_value(const std::string& json, const std::string& key) {
  const std::string quoted = "\"" + key + "\":";
  const std::size_t at = json.find(quoted);
  if (at == std::string::npos) return "";
  std::size_t i = json.find_first_not_of(" \t\r\n", at + quoted.size());
  if (i == std::string::npos) return "";
  if (json[i] == '"') {
    const std::size_t end = json.find('"', i + 1);
    return end == std::string::npos ? "" : json.substr(i + 1, end - i - 1);
  }
  const std::size_t end = json.find_first_of(",}\r\n", i);
  std::string v = json.substr(i, end == std::string::npos ? std::string::npos : end - i);
  while (!v.empty() && (v.back() == ' ' || v.back() == '\t')) v.pop_back();
  return v;
}

struct Sample {
  double x = 0, y = 0;
  long seg = 0;
  bool torch = false;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: sim_corpus_check FILE TRACE.csv REPORT.json TOL\n");
    return 2;
  }
  const std::string file = argv[1];
  const double tol = std::atof(argv[4]);
  int failures = 0;
  auto fail = [&](const std::string& what) {
    std::fprintf(stderr, "FAIL %s: %s\n", file.c_str(), what.c_str());
    ++failures;
  };

  std::string report;
  if (!read_file(argv[3], report)) return fail("no report"), 1;
  const std::string state = json_value(report, "state");
  const long planned = std::atol(json_value(report, "segments_planned").c_str());
  const long executed = std::atol(json_value(report, "segments_executed").c_str());
  const long total = std::atol(json_value(report, "segments_executed_total").c_str());
  const long duplicates = std::atol(json_value(report, "duplicates").c_str());
  if (state != "done") fail("state " + state + ", not done");
  if (planned <= 0) fail("no segments planned");
  if (executed != planned || total != planned)
    fail("executed " + std::to_string(executed) + " (" + std::to_string(total) + " in all) of " +
         std::to_string(planned) + " segments");
  if (duplicates != 0) fail(std::to_string(duplicates) + " segments ran twice");

  std::string trace_text;
  if (!read_file(argv[2], trace_text)) return fail("no trace"), 1;
  std::vector<Sample> trace;
  {
    std::istringstream in(trace_text);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      Sample s;
      double t = 0;
      int torch = 0;
      if (std::sscanf(line.c_str(), "%lf,%lf,%lf,%ld,%d", &t, &s.x, &s.y, &s.seg, &torch) != 5)
        return fail("unreadable trace line: " + line), 1;
      s.torch = torch != 0;
      trace.push_back(s);
    }
  }
  long last = 0;
  for (const Sample& s : trace) {
    if (s.seg == 0) continue;
    if (s.seg < last) {
      fail("segment " + std::to_string(s.seg) + " runs again after segment " + std::to_string(last));
      break;
    }
    last = s.seg;
  }
  const long last_executed = std::atol(json_value(report, "last_executed_segment").c_str());
  if (last_executed != planned || last > planned)
    fail("the last segment run is " + std::to_string(last_executed) + " (trace: " + std::to_string(last) + ") of " +
         std::to_string(planned));

  const kerf_test::Toolpath path = kerf_test::read_toolpath(file);
  if (!path.ok) return fail("the independent reader refuses it: " + path.error), 1;
  const kerf_test::MoveIndex index(kerf_test::cut_moves(path), 2.0);
  if (index.size() == 0) return fail("no cut moves in the file"), 1;
  const double limit = tol + kSlack;
  double worst = 0;
  Sample at_worst;
  std::size_t checked = 0;
  for (const Sample& s : trace) {
    const bool cutting = path.uses_torch ? s.torch : s.seg > 0;
    if (!cutting) continue;
    ++checked;
    const double d = index.nearest({s.x, s.y}, limit);
    if (d > worst) worst = d, at_worst = s;
  }
  if (checked == 0) fail("no torch-on setpoint in the trace");
  if (worst > limit) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "setpoint (%.4f, %.4f) of segment %ld is %.4f mm from the file's toolpath (limit %.4f)",
                  at_worst.x, at_worst.y, at_worst.seg, worst, limit);
    fail(buf);
  }
  std::printf("%s: %s, %ld segments run once each, %zu %s setpoints checked against %zu cut moves, worst %.4f mm "
              "(tol %.3f + %.3f)\n",
              file.c_str(), state.c_str(), planned, checked, path.uses_torch ? "torch-on" : "dry-run cut",
              index.size(), worst, tol, kSlack);
  return failures == 0 ? 0 : 1;
}
