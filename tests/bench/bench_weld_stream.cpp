// `kerf weld` streamed on generated jobs of 1e5, 1e6 and 1e7 lines (the
// same job as tests/weld's scale test), piped through kerf's stdin and
// stdout: per size the peak RSS, the wall time, the lines per second and
// the RSS per line; for the largest, the time to the first output line
// against the time to write the whole job into kerf.
//
//   kerf_bench_weld_stream [KERF] [--threads N] [--sizes a,b,c]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "weld_pipe.hpp"

int main(int argc, char** argv) {
  std::string kerf = KERF_BIN;
  int threads = 0;
  std::vector<unsigned long long> sizes{100000, 1000000, 10000000};
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
      threads = std::atoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--sizes") == 0 && i + 1 < argc) {
      sizes.clear();
      for (char* s = argv[++i]; *s != '\0';) {
        char* end = nullptr;
        sizes.push_back(std::strtoull(s, &end, 10));
        s = *end == ',' ? end + 1 : end;
      }
    } else {
      kerf = argv[i];
    }
  }
  long first_rss = 0;
  bool ok = true;
  for (const unsigned long long n : sizes) {
    const kerf_test::PipeRun r = kerf_test::weld_pipe(kerf, n, threads, false);
    if (!r.ok) {
      std::printf("%llu lines: kerf weld failed: %s\n", n, r.err.c_str());
      ok = false;
      continue;
    }
    if (first_rss == 0) first_rss = r.max_rss_kb;
    std::printf("%9zu lines: peak RSS %6.1f MB (%.2fx the first size), %7.2f s, %5.0fk lines/s, "
                "%.1f bytes of RSS a line; first output after %.3f s, the job written in after %.2f s\n",
                r.lines, static_cast<double>(r.max_rss_kb) / 1024.0,
                static_cast<double>(r.max_rss_kb) / static_cast<double>(first_rss), r.seconds,
                static_cast<double>(r.lines) / r.seconds / 1000.0,
                static_cast<double>(r.max_rss_kb) * 1024.0 / static_cast<double>(r.lines), r.first_output,
                r.input_written);
  }
  return ok ? 0 : 1;
}
