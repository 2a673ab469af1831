#include "app/weld_command.hpp"

#include <sys/stat.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdlib>
#include <optional>
#include <string>

#include "io/input_file.hpp"
#include "io/options.hpp"
#include "io/prefault.hpp"
#include "weld/weld.hpp"

namespace kerf::app {

CLI::App* add_weld_command(CLI::App& app, WeldCommandOptions& opts) {
  CLI::App* weld = app.add_subcommand(
      "weld", "Replace the G1 polylines of a G-code file with G2/G3 arcs within --tol (mm)");
  weld->add_option("--tol", opts.tol, "Largest deviation from the input path, in mm (> 0)")
      ->type_name("EPS")
      ->required();
  weld->add_option("--criterion", opts.criterion,
                   "band (the arcs stay within tol of the polyline) or vertex (the points within "
                   "tol of their arc; the arcs are checked against the band too)")
      ->type_name("NAME")
      ->capture_default_str();
  weld->add_option("--decimals", opts.decimals,
                   "Digits after the point in the output (default: as many as the input's X/Y)")
      ->type_name("D");
  weld->add_flag("--no-split", opts.no_split,
                 "Do not fit separately at turns sharper than 90 degrees (slower, rarely fewer moves)");
  weld->add_option("--threads", opts.threads,
                   "Threads that fit polylines (default 0: one per core; 1: none besides the main one); "
                   "the output is the same for any count")
      ->type_name("N");
  weld->add_option("in", opts.in, "G-code file; - for stdin")->type_name("IN")->required();
  weld->add_option("out", opts.out, "Output file (written whole or not at all); - for stdout")
      ->type_name("OUT")
      ->required();
  return weld;
}

int run_weld(const WeldCommandOptions& opts) {
  // A weld of a large file fills tens of MB once (a 0.9 MB file's blocks
  // are 7 MB): in huge pages that is 424 page faults instead of 3735, 5 ms
  // less of 81 (tball-pocket). A small file's few pages would cost more as
  // one zeroed huge page (0.15 ms on a 15-line file).
  struct stat st {};
  if (opts.in != "-" && ::stat(opts.in.c_str(), &st) == 0 && S_ISREG(st.st_mode) && st.st_size >= (128 << 10))
    io::use_huge_page_heap(std::size_t{64} << 20);
  weld::WeldOptions w;
  std::string error;
  if (!io::parse_length("--tol", opts.tol, false, w.tol_mm, error)) return io::usage_error(error);
  const std::optional<job::Criterion> criterion = job::parse_criterion(opts.criterion);
  if (!criterion)
    return io::usage_error("--criterion: unknown criterion " + io::quoted(opts.criterion) +
                           " (expected vertex or band)");
  w.criterion = *criterion;
  if (!opts.decimals.empty()) {
    char* end = nullptr;
    errno = 0;
    const long d = std::strtol(opts.decimals.c_str(), &end, 10);
    if (errno != 0 || *end != '\0' || d < 0 || d > 9)
      return io::usage_error("--decimals: expected a whole number from 0 to 9, got " + io::quoted(opts.decimals));
    w.decimals = static_cast<int>(d);
  }
  w.split_turns = !opts.no_split;
  if (!opts.threads.empty()) {
    char* end = nullptr;
    errno = 0;
    const long n = std::strtol(opts.threads.c_str(), &end, 10);
    if (errno != 0 || end == opts.threads.c_str() || *end != '\0' || n < 0 || n > 1024)
      return io::usage_error("--threads: expected a whole number from 0 (one per core) to 1024, got " +
                             io::quoted(opts.threads));
    w.threads = static_cast<int>(n);
  }
  if (!io::input_readable(opts.in)) return io::kExitUsage;
  return weld::weld_file(opts.in, opts.out, w);
}

}  // namespace kerf::app
