// How soon `kerf sim` moves on a long program (issue 24): on a generated
// G-code file of N lines (1e7 by default: paths of 500 short G1 moves, each
// pierced), the wall time from opening the job to the first job segment
// running on the simulated board (kerf sim's own job loading,
// simulated/sim_job.hpp, then the controller over Modbus in lockstep),
// against the time to read the whole program (job::open_program_stream to
// its end, no fit), to read and fit it whole (what kerf sim did before its
// first segment when it loaded the whole job; here each path's segments are
// dropped once fitted, so this costs no memory) and to read its bytes. Peak
// RSS after each.
//
//   kerf_bench_sim_first [--lines N] [--keep FILE]
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "config/config.hpp"
#include "control/job_actions.hpp"
#include "control/machine_config.hpp"
#include "control/program_job.hpp"
#include "job/program_stream.hpp"
#include "kerf/sim/scripted_gpio.hpp"
#include "simulated/sim_job.hpp"
#include "simulated/sim_machine.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double peak_mb() {
  rusage u{};
  ::getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

bool write_program(const std::string& path, long n) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (f == nullptr) return false;
  std::fprintf(f, "G21 G90\nF6000\n");
  for (long k = 0, row = 0; k < n; k += 500, ++row) {
    const double y0 = 10.0 + 3.0 * static_cast<double>(row % 100), x0 = 10.0 + 40.0 * static_cast<double>(row / 100 % 20);
    std::fprintf(f, "G0 X%.3f Y%.3f\nM3 S1\n", x0, y0);
    for (long j = 0; j < 500 && k + j < n; ++j) {
      const double t = 0.05 * static_cast<double>(j);
      std::fprintf(f, "G1 X%.3f Y%.3f\n", x0 + t, y0 + std::sin(t / 2.0));
    }
    std::fprintf(f, "M5\n");
  }
  std::fprintf(f, "M2\n");
  return std::fclose(f) == 0;
}

// Seconds from opening the job to the board running its first segment; < 0 on failure.
double first_segment(const std::string& file) {
  using namespace kerf;
  const auto t0 = Clock::now();
  const config::Config cfg = config::defaults();
  simulated::SimJobSettings s;
  s.criterion = job::Criterion::vertex;
  s.tol = cfg.fit.tol;
  s.feed = cfg.cut.feed;
  std::unique_ptr<simulated::SimJob> job;
  if (simulated::load_sim_job(file, cfg, s, job) != 0) return -1.0;
  const double loaded = since(t0);
  control::ControllerConfig ccfg = control::controller_config(cfg);
  control::MemoryOutputs outputs;
  ccfg.outputs = &outputs;
  sim::ScriptedGpio gpio;
  simulated::SimMachineConfig m = simulated::sim_machine_config(cfg);
  m.start = job->start();
  double first = -1.0;
  m.trace_sink = [&](const sim::TraceSample& t) {
    if (first < 0.0 && t.seq != 0) first = since(t0);
  };
  m.max_sim_s = 0.0;  // stop once the first segment runs
  m.time_limit = [&first] { return first < 0.0 ? 1e12 : 0.0; };
  control::ResumePoint from;
  from.from = job->first_pierce();
  simulated::run_sim_machine(job->source(), ccfg, m, gpio, nullptr, from);
  std::printf("  job loaded (file hashed, producer started, its ring full) in %.3f s\n", loaded);
  return first;
}

// The program as kerf sim reads it (the default configuration); null on failure.
std::unique_ptr<kerf::job::ProgramStream> open_program(const std::string& file) {
  using namespace kerf;
  std::unique_ptr<job::ProgramStream> stream;
  std::string error;
  if (!job::open_program_stream(file, config::interp_settings(config::defaults(), false), job::MachineState{}, stream,
                                error))
    std::fprintf(stderr, "%s\n", error.c_str());
  return stream;
}

double read_program(const std::string& file, std::size_t& paths) {
  using namespace kerf;
  const auto t0 = Clock::now();
  const std::unique_ptr<job::ProgramStream> stream = open_program(file);
  if (!stream) return -1.0;
  std::printf("  open_program_stream (its scan of every line) took %.3f s\n", since(t0));
  job::ProgramPiece path;
  job::ProgramAction action;
  paths = 0;
  for (job::ProgramStream::Next n; (n = stream->next(path, action)) != job::ProgramStream::Next::end;) {
    if (n == job::ProgramStream::Next::error) return -1.0;
    paths += n == job::ProgramStream::Next::path;
  }
  return since(t0);
}

// The whole program read and every path fitted as kerf sim fits it (vertex,
// the configuration's tol and feeds), the segments dropped; < 0 on failure.
double read_and_fit(const std::string& file, std::size_t& segments) {
  using namespace kerf;
  const auto t0 = Clock::now();
  const config::Config cfg = config::defaults();
  const std::unique_ptr<job::ProgramStream> stream = open_program(file);
  if (!stream) return -1.0;
  std::string error;
  control::PathFitSettings fs;
  fs.criterion = job::Criterion::vertex;
  fs.tol = cfg.fit.tol;
  fs.feed_mm_s = cfg.cut.feed / 60.0;
  fs.max_feed_mm_s = cfg.machine.max_feed / 60.0;
  job::ProgramPiece path;
  job::ProgramAction action;
  io::PointFile one;
  one.file = file;
  segments = 0;
  for (std::size_t p = 0;; ++p) {
    const job::ProgramStream::Next n = stream->next(path, action);
    if (n == job::ProgramStream::Next::end) break;
    if (n == job::ProgramStream::Next::error) return -1.0;
    if (n != job::ProgramStream::Next::path) continue;
    one.points = path.points;
    one.point_lines = path.lines;
    control::FittedJob out;
    if (control::fit_program_path(one, path.feed, path.path, p, fs, out, error) != 0) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return -1.0;
    }
    for (const control::CutPath& c : out.job.paths) segments += c.segments.size();
  }
  return since(t0);
}

double read_bytes(const std::string& file) {
  const auto t0 = Clock::now();
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if (f == nullptr) return -1.0;
  static char buf[1 << 16];
  while (std::fread(buf, 1, sizeof buf, f) > 0) {
  }
  std::fclose(f);
  return since(t0);
}

}  // namespace

int main(int argc, char** argv) {
  long lines = 10000000;
  std::string keep;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--lines" && i + 1 < argc) lines = std::strtol(argv[++i], nullptr, 10);
    else if (a == "--keep" && i + 1 < argc) keep = argv[++i];
    else {
      std::fprintf(stderr, "usage: %s [--lines N] [--keep FILE]\n", argv[0]);
      return 2;
    }
  }
  const std::string file = keep.empty() ? "/tmp/kerf_bench_sim_first_" + std::to_string(::getpid()) + ".ngc" : keep;
  if (keep.empty() || ::access(file.c_str(), R_OK) != 0) {
    const auto t0 = Clock::now();
    if (!write_program(file, lines)) return 1;
    std::printf("wrote %ld lines to %s in %.1f s\n", lines, file.c_str(), since(t0));
  }
  std::fflush(stdout);
  std::printf("its bytes read in %.3f s\n", read_bytes(file));
  const double first = first_segment(file);
  std::printf("first segment on the board after %.3f s (peak RSS %.1f MB)\n", first, peak_mb());
  std::fflush(stdout);
  std::size_t paths = 0;
  const double whole = read_program(file, paths);
  std::printf("whole program read (open_program_stream to its end, %zu paths) in %.3f s (peak RSS %.1f MB)\n", paths,
              whole, peak_mb());
  if (first > 0.0 && whole > 0.0) std::printf("first segment / whole read: %.3f\n", first / whole);
  std::size_t segments = 0;
  const double fitted = read_and_fit(file, segments);
  std::printf("whole job read and fitted (%zu segments, as kerf sim loaded it before streaming) in %.3f s\n", segments,
              fitted);
  if (first > 0.0 && fitted > 0.0) std::printf("first segment / whole read and fit: %.3f\n", first / fitted);
  if (keep.empty()) std::remove(file.c_str());
  return first > 0.0 && whole > 0.0 && fitted > 0.0 ? 0 : 1;
}
