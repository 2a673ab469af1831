// How fast `kerf-sim sim --speed 0` runs jobs, as a user runs it: per job,
// the simulated time, the wall time of the lockstep run (the report's
// wall_s) and of the whole process (spawn to exit, fitting included), the
// ratios of simulated to wall time, and the peak RSS (from wait4).
//
//   kerf_bench_sim [--kerf-sim PATH] [--baseline PATH] [--spiral N] [--quick]
//
// Jobs: the built-in demo, the corpus files tests/data/gcode/cncjs_tball-engrave.gcode,
// cncjs_jsdc-laser.gcode and cncjs_tball-pocket.gcode, and a generated
// spiral of N G1 lines (100000 by default, about 2200 s simulated).
// --baseline runs another kerf-sim (an older build) on the same jobs in the
// same run, so that before and after are measured side by side.
// --quick: the demo and the engraving only.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Run {
  bool ok = false;
  long rss_kb = 0;
  double process_s = 0, sim_s = 0, loop_s = 0;
};

double json_number(const std::string& text, const std::string& key) {
  const std::size_t at = text.find("\"" + key + "\":");
  return at == std::string::npos ? -1.0 : std::strtod(text.c_str() + at + key.size() + 3, nullptr);
}

Run run(const std::string& bin, const std::string& job, const std::string& dir) {
  Run r;
  const std::string report = dir + "/bench_sim_report.json";
  std::remove(report.c_str());
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) return r;
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);  // not a terminal: no progress line
    if (chdir(dir.c_str()) != 0) _exit(127);
    if (job.empty())  // the demo writes its trace, plot and report here
      execl(bin.c_str(), bin.c_str(), "sim", "--report", report.c_str(), static_cast<char*>(nullptr));
    else
      execl(bin.c_str(), bin.c_str(), "sim", "--report", report.c_str(), job.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage use{};
  if (wait4(pid, &status, 0, &use) != pid) return r;
  r.process_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.rss_kb = use.ru_maxrss;
  std::ifstream in(report);
  std::stringstream text;
  text << in.rdbuf();
  r.sim_s = json_number(text.str(), "duration_s");
  r.loop_s = json_number(text.str(), "wall_s");
  r.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0 && r.sim_s > 0 && r.loop_s > 0;
  return r;
}

// n G1 lines along an Archimedean spiral (2 mm between turns, about 1.1 mm
// a line) at F3000: about 2200 s of cutting for n = 100000.
bool write_spiral(const std::string& path, long n) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) return false;
  std::fprintf(f, "G21 G90\nF3000\nG0 X0 Y0\nM3 S1\n");
  double theta = 0.5;
  const double a = 2.0 / (2.0 * M_PI);
  for (long k = 0; k < n; ++k) {
    const double r = a * theta;
    std::fprintf(f, "G1 X%.4f Y%.4f\n", r * std::cos(theta), r * std::sin(theta));
    theta += 1.1 / std::max(r, 1.0);
  }
  std::fprintf(f, "M5\nM2\n");
  return std::fclose(f) == 0;
}

void print(const char* who, const Run& r) {
  if (!r.ok) {
    std::printf("  %-9s FAILED\n", who);
    return;
  }
  std::printf("  %-9s %9.1f s simulated  run %7.2f s (%6.0fx)  process %7.2f s (%6.0fx)  peak RSS %7ld KiB\n", who,
              r.sim_s, r.loop_s, r.sim_s / r.loop_s, r.process_s, r.sim_s / r.process_s, r.rss_kb);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::string bin = KERF_SIM_BIN, baseline;
  long spiral = 100000;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--kerf-sim" && has_value) bin = argv[++i];
    else if (a == "--baseline" && has_value) baseline = argv[++i];
    else if (a == "--spiral" && has_value) spiral = std::strtol(argv[++i], nullptr, 10);
    else if (a == "--quick") quick = true;
    else {
      std::fprintf(stderr, "usage: %s [--kerf-sim PATH] [--baseline PATH] [--spiral N] [--quick]\n", argv[0]);
      return 2;
    }
  }
  char tmpl[] = "/tmp/kerf_bench_sim_XXXXXX";
  const char* dir = mkdtemp(tmpl);
  if (dir == nullptr) return 1;
  const std::string data = KERF_GCODE_DIR;
  std::vector<std::pair<std::string, std::string>> jobs = {{"demo", ""},
                                                           {"engrave", data + "/cncjs_tball-engrave.gcode"}};
  if (!quick) {
    jobs.push_back({"laser", data + "/cncjs_jsdc-laser.gcode"});
    jobs.push_back({"pocket", data + "/cncjs_tball-pocket.gcode"});
    const std::string path = std::string(dir) + "/spiral.ngc";
    if (!write_spiral(path, spiral)) return 1;
    jobs.push_back({"spiral " + std::to_string(spiral), path});
  }
  std::printf("kerf-sim sim --speed 0: %s%s%s\n", bin.c_str(), baseline.empty() ? "" : " against ",
              baseline.c_str());
  bool ok = true;
  for (const auto& [name, job] : jobs) {
    std::printf("%s\n", name.c_str());
    if (!baseline.empty()) print("baseline", run(baseline, job, dir));
    const Run r = run(bin, job, dir);
    print("kerf-sim", r);
    ok = ok && r.ok;
  }
  const std::string cleanup = std::string("rm -rf ") + dir;
  if (std::system(cleanup.c_str()) != 0) return 1;
  return ok ? 0 : 1;
}
