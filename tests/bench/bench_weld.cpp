// `kerf weld` on the G-code corpus (tests/data/gcode): per file, the reader's
// and the welder's lines per second and the output/input move ratio at
// tol 0.025 mm, with the ArcWelder ratios issue 10 quotes and a greedy
// welder measured here (greedy_moves) for comparison.
// Prints figures measured in this run; it asserts nothing about speed.
//
// Times are CPU seconds of this process, single-threaded; "weld lines/s"
// includes the read. The first read and weld of a file run as `kerf weld`
// does, on memory the process has not touched yet (page faults are a large
// part of the read); "warm" is the fastest of --repeat runs of both, on
// memory already mapped. "vs 700k" is the first run's weld lines/s over the
// ~700k lines/s issue 10 quotes for ArcWelder.
//
// Last, "whole process": the built `kerf weld --tol TOL --criterion C IN OUT`
// run --repeat times (at least 5; 11 for wall time) as a child process,
// from exec to exit: startup, reading, welding, writing and freeing, as a
// user runs it; median and best of the runs. First with --threads 1 on the
// largest file (bytes), its CPU time (user + system, from wait4's rusage):
// the sequential weld's cost. Then as a user runs it, one thread per core
// (--threads 0), on the file with the most lines (tball-pocket), its wall
// time: issue 10's lines/s against ArcWelder's 700k.
//
// Then "threads" (unless --no-threads): each file welded in this process
// with threads = 1 and threads = 2 (WeldOptions::threads), alternately,
// --repeat runs each (at least 5): the fastest wall time of each (the pool's
// point is wall time; CPU time adds the threads up), its lines/s, their
// ratio, and whether the two outputs are the same bytes (exit 1 if not).
// The reader is not timed.
//
// With --arcwelder PATH, last, "side by side": per file, ArcWelder
// (FormerLurker/ArcWelderLib's console program, at that path) and the built
// `kerf weld --threads 1`, run alternately as child processes at the same
// largest deviation, best wall time and best CPU time (user + system, from
// wait4: steadier on a shared machine) of max(--repeat, 11) runs each, and
// kerf's time over ArcWelder's. ArcWelder's resolution is the band's whole
// width (it allows +-resolution/2), so it runs with -r=2*TOL, and with -y
// (travel arcs): without it ArcWelder welds only moves that extrude (E), so a
// cutting file with no E word is copied through unwelded. The lines each
// wrote are printed, to show that both welded. Without the option (CI has no
// ArcWelder) nothing of it runs.
//
// usage: kerf_bench_weld [--criterion band|vertex|both] [--tol MM] [--no-split] [--jitter F]
//                        [--tie-break R] [--no-greedy] [--repeat N] [--dump DIR]
//                        [--kerf PATH | --no-process] [--no-threads] [--arcwelder PATH] [FILE...]
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "weld/weld.hpp"
#include "job/gcode_reader.hpp"

namespace {

// CPU time of this process (single-threaded): the machine is shared, and
// wall time would count the other processes' share.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// A greedy welder in ArcWelder's manner, as a baseline measured here: from
// each piece's start, extend the piece one point at a time while the circle
// through its first, middle and last point (or the line, when no circle
// fits) keeps every inner point within tol and, at samples tol/4 apart, stays
// within tol of the polyline (at most 256 samples); stop at the first
// point that fails. Returns the
// pieces (moves) for one run.
using P = kerf::Vec2<double>;

double seg_dist(P a, P b, P p) {
  const P d = b - a;
  const double l2 = d.norm2();
  double t = l2 > 0 ? d.dot(p - a) / l2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return (p - (a + d * t)).norm();
}

bool fits(const std::vector<P>& p, std::size_t i, std::size_t j, double tol) {
  const P a = p[i], m = p[(i + j) / 2], b = p[j];
  // Circumcentre of a, m, b.
  const double d = 2 * ((m - a).cross(b - a));
  bool arc = std::fabs(d) > 1e-12 && j - i >= 2;
  P c{};
  double r = 0;
  if (arc) {
    const P u = m - a, v = b - a;
    c = a + P{(v.y * u.norm2() - u.y * v.norm2()) / d, (u.x * v.norm2() - v.x * u.norm2()) / d};
    r = (a - c).norm();
    arc = r < 1e6;
  }
  auto on_piece = [&](double t) {  // t in [0,1] along the piece
    if (!arc) return a + (b - a) * t;
    const double a0 = std::atan2(a.y - c.y, a.x - c.x);
    double sweep = std::atan2(b.y - c.y, b.x - c.x) - a0;
    const bool ccw = (m - a).cross(b - a) > 0;  // a left turn at m
    if (ccw && sweep < 0) sweep += 2 * M_PI;
    if (!ccw && sweep > 0) sweep -= 2 * M_PI;
    return P{c.x + r * std::cos(a0 + sweep * t), c.y + r * std::sin(a0 + sweep * t)};
  };
  double length = 0;
  for (int k = 1; k <= 8; ++k) length += (on_piece(k / 8.0) - on_piece((k - 1) / 8.0)).norm();
  const int n = std::clamp(static_cast<int>(std::ceil(4 * length / tol)), 8, 256);  // as kerf weld's cap
  // The piece near the polyline, and every inner point near the piece.
  for (int k = 1; k < n; ++k) {
    const P q = on_piece(static_cast<double>(k) / n);
    double best = 1e300;
    for (std::size_t s = i; s < j; ++s) best = std::min(best, seg_dist(p[s], p[s + 1], q));
    if (best > tol) return false;
  }
  for (std::size_t k = i + 1; k < j; ++k) {
    double best = 1e300;
    P prev = a;
    for (int t = 1; t <= n; ++t) {
      const P q = on_piece(static_cast<double>(t) / n);
      best = std::min(best, seg_dist(prev, q, p[k]));
      prev = q;
    }
    if (best > tol) return false;
  }
  return true;
}

std::size_t greedy_moves(const std::vector<P>& p, double tol) {
  std::size_t moves = 0;
  for (std::size_t i = 0; i + 1 < p.size();) {
    std::size_t j = i + 1;
    while (j + 1 < p.size() && fits(p, i, j + 1, tol)) ++j;
    ++moves;
    i = j;
  }
  return moves;
}

std::size_t greedy_file(const kerf::job::GcodeFile& g, double tol_mm) {
  std::size_t moves = 0, replaced = 0;
  for (const kerf::job::GPolyline& pl : g.polylines) {
    std::vector<P> p;
    for (const P& q : pl.points)
      if (p.empty() || !(p.back() == q)) p.push_back(q);
    replaced += pl.points.size() - 1;
    moves += p.size() < 2 || pl.relative ? pl.points.size() - 1 : greedy_moves(p, tol_mm / (pl.inches ? 25.4 : 1.0));
  }
  std::size_t all = 0;
  for (const kerf::job::GBlock& b : g.blocks) all += b.moves ? 1 : 0;
  return all - replaced + moves;
}

// ArcWelder at 0.025 mm, travel arcs allowed (issue 10); 0 when not quoted.
double arcwelder_ratio(const std::string& path) {
  if (path.find("jsdc-laser") != std::string::npos) return 0.037;
  if (path.find("tball-engrave") != std::string::npos) return 0.025;
  if (path.find("tball-pocket") != std::string::npos) return 0.069;
  return 0;
}

// CPU seconds (user + system) and wall seconds of `argv` run as a child
// process; false when it could not run or failed.
bool run_child(const std::vector<std::string>& args, double& cpu, double& wall) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const auto t0 = std::chrono::steady_clock::now();
  const int err = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) return false;
  int status = 0;
  rusage ru{};
  if (wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return false;
  wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  cpu = seconds(ru.ru_utime) + seconds(ru.ru_stime);
  return true;
}

// A whole-process figure (see the top of this file): `kerf weld --threads
// THREADS` on `path`, median and best of the runs, of CPU time (wall =
// false) or wall time. False when kerf failed.
bool whole_process(const std::string& kerf, const std::string& path, std::size_t lines, double tol,
                   const std::string& criterion, int repeat, const std::string& threads, bool wall) {
  const std::string out = (std::filesystem::temp_directory_path() /
                           ("kerf_bench_weld." + std::to_string(::getpid()) + ".nc")).string();
  char tol_text[32];
  std::snprintf(tol_text, sizeof tol_text, "%.10g", tol);
  std::vector<double> runs, cpu_runs;
  // Wall time varies more than CPU time (the other core's load): more runs.
  for (int r = 0; r < std::max(repeat, wall ? 11 : 5); ++r) {
    double cpu = 0, wall_s = 0;
    if (!run_child({kerf, "weld", "--threads", threads, "--tol", tol_text, "--criterion", criterion, path, out}, cpu,
                   wall_s)) {
      std::fprintf(stderr, "kerf_bench_weld: %s weld failed on %s\n", kerf.c_str(), path.c_str());
      std::filesystem::remove(out);
      return false;
    }
    runs.push_back(wall ? wall_s : cpu);
    cpu_runs.push_back(cpu);
  }
  std::filesystem::remove(out);
  std::sort(runs.begin(), runs.end());
  std::sort(cpu_runs.begin(), cpu_runs.end());
  const double median = runs[runs.size() / 2], best = runs.front();
  const double n = static_cast<double>(lines);
  std::printf("\nwhole process: kerf weld --threads %s --tol %s --criterion %s %s OUT (%zu lines), %s of %zu runs\n",
              threads.c_str(), tol_text, criterion.c_str(), path.substr(path.find_last_of('/') + 1).c_str(), lines,
              wall ? "wall time" : "CPU time", runs.size());
  std::printf("  median %.1f ms: %.0f lines/s, %.2fx 700k; best %.1f ms: %.0f lines/s, %.2fx 700k\n",
              1e3 * median, n / median, n / median / 700e3, 1e3 * best, n / best, n / best / 700e3);
  if (wall) std::printf("  (CPU time: median %.1f ms, %.2f cores busy)\n", 1e3 * cpu_runs[cpu_runs.size() / 2],
                        cpu_runs[cpu_runs.size() / 2] / median);
  return true;
}

std::size_t count_lines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines;
}

// The "side by side" figures (see the top of this file); false when either
// program failed.
bool side_by_side(const std::string& kerf, const std::string& arcwelder, const std::vector<std::string>& files,
                  double tol, const std::string& criterion, int repeat) {
  const std::string tmp = std::filesystem::temp_directory_path().string() + "/kerf_bench_weld." +
                          std::to_string(::getpid());
  char tol_text[32], resolution[48];
  std::snprintf(tol_text, sizeof tol_text, "%.10g", tol);
  std::snprintf(resolution, sizeof resolution, "-r=%.10g", 2 * tol);
  const int runs = std::max(repeat, 11);
  std::printf("\nside by side: %s -p=NONE -l=ERROR -y %s IN OUT and kerf weld --threads 1 --tol %s --criterion %s "
              "IN OUT\n(the same largest deviation, %s mm), alternately, best wall and CPU time of %d runs each\n",
              arcwelder.c_str(), resolution, tol_text, criterion.c_str(), tol_text, runs);
  std::printf("%-46s %7s %13s %9s %10s %14s %10s %10s %9s %9s\n", "file", "lines", "arcwelder ms", "kerf ms",
              "kerf / aw", "arcwelder cpu", "kerf cpu", "kerf / aw", "aw out", "kerf out");
  bool ok = true;
  for (const std::string& path : files) {
    const std::size_t lines = count_lines(path);
    double best[2] = {1e300, 1e300}, best_cpu[2] = {1e300, 1e300};
    for (int r = 0; r < runs && ok; ++r) {
      double cpu = 0, wall = 0;
      ok = run_child({arcwelder, "-p=NONE", "-l=ERROR", "-y", resolution, path, tmp + ".aw.gcode"}, cpu, wall);
      if (!ok) {
        std::fprintf(stderr, "kerf_bench_weld: %s failed on %s\n", arcwelder.c_str(), path.c_str());
        break;
      }
      best[0] = std::min(best[0], wall);
      best_cpu[0] = std::min(best_cpu[0], cpu);
      ok = run_child({kerf, "weld", "--threads", "1", "--tol", tol_text, "--criterion", criterion, path,
                      tmp + ".kerf.nc"}, cpu, wall);
      if (!ok) {
        std::fprintf(stderr, "kerf_bench_weld: %s weld failed on %s\n", kerf.c_str(), path.c_str());
        break;
      }
      best[1] = std::min(best[1], wall);
      best_cpu[1] = std::min(best_cpu[1], cpu);
    }
    if (!ok) break;
    std::printf("%-46s %7zu %13.2f %9.2f %9.2fx %14.2f %10.2f %9.2fx %9zu %9zu\n",
                path.substr(path.find_last_of('/') + 1).c_str(), lines, 1e3 * best[0], 1e3 * best[1],
                best[1] / best[0], 1e3 * best_cpu[0], 1e3 * best_cpu[1], best_cpu[1] / best_cpu[0],
                count_lines(tmp + ".aw.gcode"), count_lines(tmp + ".kerf.nc"));
    std::fflush(stdout);
  }
  std::filesystem::remove(tmp + ".aw.gcode");
  std::filesystem::remove(tmp + ".kerf.nc");
  return ok;
}

// One line of the "threads" figures (see the top of this file); false when
// a weld failed or the two outputs differ.
bool threads_figure(const kerf::job::GcodeFile& g, kerf::weld::WeldOptions o, int repeat) {
  double best[2] = {1e300, 1e300};
  std::string out[2];
  for (int r = 0; r < std::max(repeat, 5); ++r) {
    for (int k = 0; k < 2; ++k) {
      o.threads = k + 1;
      std::string once, error;
      kerf::weld::WeldStats st;
      const auto t0 = std::chrono::steady_clock::now();
      if (!kerf::weld::weld_gcode(g, o, once, st, error)) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return false;
      }
      best[k] = std::min(best[k], std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      if (r == 0) out[k].swap(once);
    }
  }
  const double lines = static_cast<double>(g.blocks.size());
  const std::string name = g.file.substr(g.file.find_last_of('/') + 1);
  std::printf("%-46s %-7s %8.1f %12.0f %8.1f %12.0f %6.2fx %5s\n", name.c_str(), kerf::job::to_string(o.criterion),
              1e3 * best[0], lines / best[0], 1e3 * best[1], lines / best[1], best[0] / best[1],
              out[0] == out[1] ? "yes" : "NO");
  return out[0] == out[1];
}

constexpr const char* kUsage =
    "usage: kerf_bench_weld [--criterion band|vertex|both] [--tol MM] [--no-split] [--jitter F]\n"
    "                       [--tie-break R] [--no-greedy] [--repeat N] [--dump DIR]\n"
    "                       [--kerf PATH | --no-process] [--no-threads] [--arcwelder PATH] [FILE...]\n";

}  // namespace

int main(int argc, char** argv) {
  double tol = 0.025;
  std::vector<std::string> criteria{"band", "vertex"};
  bool split = true;
  double jitter = kerf::weld::WeldOptions{}.jitter;
  double tie_break = kerf::weld::WeldOptions{}.tie_break;
  std::string dump;  // a directory to write each output to
  bool with_greedy = true;
  int repeat = 3;
  std::string kerf = KERF_BIN;
  bool with_process = true;  // the whole-process figures
  bool with_threads = true;
  std::string arcwelder;  // empty: no side-by-side figures
  std::vector<std::string> files;
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--tol") == 0 && k + 1 < argc) tol = std::atof(argv[++k]);
    else if (std::strcmp(argv[k], "--criterion") == 0 && k + 1 < argc) {
      const std::string c = argv[++k];
      criteria = c == "both" ? std::vector<std::string>{"band", "vertex"} : std::vector<std::string>{c};
    } else if (std::strcmp(argv[k], "--no-split") == 0) split = false;
    else if (std::strcmp(argv[k], "--jitter") == 0 && k + 1 < argc) jitter = std::atof(argv[++k]);
    else if (std::strcmp(argv[k], "--tie-break") == 0 && k + 1 < argc) tie_break = std::atof(argv[++k]);
    else if (std::strcmp(argv[k], "--dump") == 0 && k + 1 < argc) dump = argv[++k];
    else if (std::strcmp(argv[k], "--no-greedy") == 0) with_greedy = false;
    else if (std::strcmp(argv[k], "--kerf") == 0 && k + 1 < argc) kerf = argv[++k];
    else if (std::strcmp(argv[k], "--no-process") == 0) with_process = false;
    else if (std::strcmp(argv[k], "--no-threads") == 0) with_threads = false;
    else if (std::strcmp(argv[k], "--arcwelder") == 0 && k + 1 < argc) arcwelder = argv[++k];
    else if (std::strcmp(argv[k], "--repeat") == 0 && k + 1 < argc) repeat = std::max(1, std::atoi(argv[++k]));
    else if (argv[k][0] == '-') {  // --help, or an option not above: say how
      std::fprintf(std::strcmp(argv[k], "--help") == 0 ? stdout : stderr, "%s", kUsage);
      return std::strcmp(argv[k], "--help") == 0 ? 0 : 2;
    } else files.emplace_back(argv[k]);
  }
  if (files.empty())
    for (const char* f : {"cncjs_jsdc-laser.gcode", "cncjs_tball-engrave.gcode", "cncjs_tball-pocket.gcode",
                          "cncjs_Circle_Diamond_Square_Calibration.gcode", "../print/cncjs_sample_slic3r.gcode",
                          "../print/cncjs_octocat.gcode"})
      files.push_back(std::string(KERF_GCODE_DIR) + "/" + f);
  std::printf("tol %.4g mm, split at sharp turns: %s, jitter %.3g tol, fastest of %d runs\n", tol,
              split ? "yes" : "no", jitter, repeat);
  std::printf("%-46s %-7s %8s %8s %7s %9s %8s %12s %12s %7s %12s\n", "file", "crit", "in", "out", "ratio",
              "arcwelder", "greedy", "read lines/s", "weld lines/s", "vs 700k", "warm weld");
  std::string largest;
  std::uintmax_t largest_bytes = 0;
  std::size_t largest_lines = 0;
  std::string longest;  // the most lines
  std::size_t longest_lines = 0;
  for (const std::string& path : files) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    double t0 = cpu_seconds();
    const kerf::job::GcodeFile g = kerf::job::parse_gcode(text, path);
    const double read_s = cpu_seconds() - t0;
    double warm_read_s = read_s;
    for (int r = 1; r < repeat; ++r) {
      const double t = cpu_seconds();
      const kerf::job::GcodeFile again = kerf::job::parse_gcode(text, path);
      warm_read_s = std::min(warm_read_s, cpu_seconds() - t);
    }
    if (!g.ok) {
      std::fprintf(stderr, "%s\n", kerf::job::describe_error(g).c_str());
      return 1;
    }
    if (text.size() >= largest_bytes) {
      largest = path;
      largest_bytes = text.size();
      largest_lines = g.blocks.size();
    }
    if (g.blocks.size() >= longest_lines) {
      longest = path;
      longest_lines = g.blocks.size();
    }
    const std::size_t greedy = with_greedy ? greedy_file(g, tol) : 0;
    for (const std::string& c : criteria) {
      kerf::weld::WeldOptions o;
      o.threads = 1;  // CPU time below: one thread's
      o.tol_mm = tol;
      o.criterion = *kerf::job::parse_criterion(c);
      o.split_turns = split;
      o.jitter = jitter;
      o.tie_break = tie_break;
      std::string out, error;
      kerf::weld::WeldStats st;
      double weld_s = 0, warm_s = 1e300;
      for (int r = 0; r < repeat; ++r) {
        std::string once;
        t0 = cpu_seconds();
        if (!kerf::weld::weld_gcode(g, o, once, st, error)) {
          std::fprintf(stderr, "%s\n", error.c_str());
          return 1;
        }
        const double t = cpu_seconds() - t0;
        if (r == 0) weld_s = t + read_s;
        warm_s = std::min(warm_s, t);
        if (r == 0) out.swap(once);
      }
      warm_s += warm_read_s;
      if (!dump.empty()) {  // the output, to compare runs byte for byte
        std::ofstream(dump + "/" + path.substr(path.find_last_of('/') + 1) + "." + c, std::ios::binary) << out;
      }
      const double lines = static_cast<double>(g.blocks.size());
      const std::string name = path.substr(path.find_last_of('/') + 1);
      std::printf("%-46s %-7s %8zu %8zu %6.2f%% %8.1f%% %7.2f%% %12.0f %12.0f %6.2fx %12.0f\n", name.c_str(),
                  c.c_str(),
                  st.input_moves, st.output_moves,
                  100.0 * static_cast<double>(st.output_moves) / static_cast<double>(st.input_moves),
                  100.0 * arcwelder_ratio(path),
                  100.0 * static_cast<double>(greedy) / static_cast<double>(st.input_moves), lines / read_s,
                  lines / weld_s, lines / weld_s / 700e3, lines / warm_s);
      std::fflush(stdout);
    }
  }
  if (with_process && !largest.empty() &&
      (!whole_process(kerf, largest, largest_lines, tol, criteria.front(), repeat, "1", false) ||
       !whole_process(kerf, longest, longest_lines, tol, criteria.front(), repeat, "0", true)))
    return 1;
  if (with_threads) {
    std::printf("\nthreads: weld wall time, fastest of %d runs each, threads=1 and threads=2 (%u cores)\n",
                std::max(repeat, 5), kerf::weld::weld_threads(0));
    std::printf("%-46s %-7s %8s %12s %8s %12s %7s %5s\n", "file", "crit", "1: ms", "1: lines/s", "2: ms",
                "2: lines/s", "2 / 1", "same");
    for (const std::string& path : files) {
      const kerf::job::GcodeFile g = kerf::job::read_gcode(path);  // not timed here
      if (!g.ok) {
        std::fprintf(stderr, "%s\n", kerf::job::describe_error(g).c_str());
        return 1;
      }
      for (const std::string& c : criteria) {
        kerf::weld::WeldOptions o;
        o.tol_mm = tol;
        o.criterion = *kerf::job::parse_criterion(c);
        o.split_turns = split;
        o.jitter = jitter;
        o.tie_break = tie_break;
        if (!threads_figure(g, o, repeat)) return 1;
      }
    }
  }
  if (!arcwelder.empty()) {
    if (!side_by_side(kerf, arcwelder, files, tol, criteria.front(), repeat)) return 1;
  }
  return 0;
}
