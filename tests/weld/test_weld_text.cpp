// kerf weld on real files' text: line ends kept as the file has them (LF,
// CRLF, CR CR LF, CR only), read back the same by an LF-only reader and a
// CR-or-LF one; a repeated F or Z is modal noise, a changed one splits.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../gcode/weld_checker.hpp"
#include "job/gcode_reader.hpp"
#include "weld/weld.hpp"

namespace {

namespace fs = std::filesystem;
using kerf::weld::WeldOptions;
using kerf::weld::WeldStats;

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

std::string weld_whole(const std::string& text, double tol, WeldStats* stats = nullptr) {
  const kerf::job::GcodeFile g = kerf::job::parse_gcode(text, "job.nc");
  EXPECT_TRUE(g.ok) << kerf::job::describe_error(g);
  WeldOptions o;
  o.tol_mm = tol;
  std::string out, error;
  WeldStats s;
  EXPECT_TRUE(kerf::weld::weld_gcode(g, o, out, s, error)) << error;
  if (stats != nullptr) *stats = s;
  return out;
}

std::string weld_streamed(const std::string& text, double tol) {
  std::string copy = text;
  std::FILE* f = fmemopen(copy.data(), copy.size(), "rb");
  WeldOptions o;
  o.tol_mm = tol;
  o.decimals = 4;  // the file's
  kerf::weld::StreamOptions so;
  so.chunk_bytes = 64;  // a part every line or two: line ends cut at every place
  std::string out, error;
  WeldStats s;
  EXPECT_EQ(kerf::weld::weld_stream(
                f, "job.nc", [&](const std::string& t) { return out += t, true; }, o, so, s, error),
            kerf::weld::StreamEnd::ok)
      << error;
  std::fclose(f);
  return out;
}

// A reader that ends lines at LF only (as LinuxCNC's does), CRs before it
// dropped as blanks.
std::vector<std::string> lf_lines(const std::string& s) {
  std::vector<std::string> lines;
  std::string cur;
  for (const char c : s) {
    if (c == '\n') {
      while (!cur.empty() && cur.back() == '\r') cur.pop_back();
      lines.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) lines.push_back(cur);
  return lines;
}

// A reader that ends a line at every CR or LF (a CR LF pair once).
std::vector<std::string> cr_or_lf_lines(const std::string& s) {
  std::vector<std::string> lines;
  std::string cur;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\r' || s[i] == '\n') {
      lines.push_back(cur);
      cur.clear();
      if (s[i] == '\r' && i + 1 < s.size() && s[i + 1] == '\n') ++i;
    } else {
      cur += s[i];
    }
  }
  if (!cur.empty()) lines.push_back(cur);
  return lines;
}

std::vector<std::string> nonblank(const std::vector<std::string>& lines) {
  std::vector<std::string> out;
  for (const std::string& l : lines)
    if (!l.empty()) out.push_back(l);
  return out;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

std::size_t blank_lines(const std::string& text) {
  const kerf::job::GcodeFile g = kerf::job::parse_gcode(text, "job.nc");
  std::size_t n = 0;
  for (const kerf::job::GBlock& b : g.blocks) n += b.text.empty() ? 1 : 0;
  return n;
}

TEST(WeldText, LineEndsAreKeptAndEveryReaderSeesTheSameProgram) {
  const fs::path dir = fs::path(KERF_TEST_SOURCE_DIR) / "line_ends";
  const std::string lf_in = slurp(dir / "quarter.nc");
  const std::string golden = slurp(dir / "quarter.expected.nc");
  const double tol = 0.01;
  for (const std::string end : {"\n", "\r\n", "\r\r\n", "\r"}) {
    const std::string in = replace_all(lf_in, "\n", end);
    const std::string what = "line end " + replace_all(replace_all(end, "\r", "CR "), "\n", "LF");
    for (const std::string& out : {weld_whole(in, tol), weld_streamed(in, tol)}) {
      // The golden, with this file's line end on every line and no other.
      EXPECT_EQ(out, replace_all(golden, "\n", end)) << what;
      EXPECT_EQ(blank_lines(out), blank_lines(in)) << what << ": a blank line the input did not have";
      // Read back by both readers: the golden's lines (a CR-or-LF reader
      // sees blank lines between a CR CR LF file's lines, nothing else),
      // and within tol of the input under the independent referee.
      std::vector<std::vector<std::string>> reads{nonblank(cr_or_lf_lines(out))};
      if (end != "\r") reads.push_back(nonblank(lf_lines(out)));
      for (const std::vector<std::string>& lines : reads) {
        EXPECT_EQ(lines, nonblank(lf_lines(golden))) << what;
        const kerf_test::WeldCheck c = kerf_test::check_weld(lf_in, joined(lines), tol);
        EXPECT_TRUE(c.ok) << what << ": " << c.why;
      }
    }
  }
}

// The quarter circle as a run of G1 lines; `extra(i)` is appended to line i.
template <class Extra>
std::string quarter(const char* before, Extra extra) {
  std::string s = std::string("G21 G90 G17\nG0 X10 Y0 Z5\n") + before;
  for (int i = 1; i <= 18; ++i) {
    char line[64];
    const double a = 5 * i * 3.14159265358979323846 / 180;
    std::snprintf(line, sizeof line, "G1 X%.4f Y%.4f", 10 * std::cos(a), 10 * std::sin(a));
    s += line + extra(i) + "\n";
  }
  return s + "G0 Z5\n";
}

TEST(WeldText, ARepeatedFeedOrZIsModalNoise) {
  WeldStats base_stats, s;
  const std::string base =
      weld_whole(quarter("G1 Z-0 F100\n", [](int i) { return std::string(i == 1 ? " F600" : ""); }), 0.01,
                 &base_stats);
  EXPECT_EQ(base_stats.polylines, 1u);
  EXPECT_EQ(base_stats.arcs, 1u);
  // F600 on every line (an Inkscape laser plugin), Z-0 on every line (a
  // sender's designer), both: the same weld, the repeated words dropped.
  EXPECT_EQ(weld_whole(quarter("G1 Z-0 F100\n", [](int) { return std::string(" F600"); }), 0.01, &s), base);
  EXPECT_EQ(s.arcs, 1u);
  EXPECT_EQ(weld_whole(quarter("G1 Z-0 F100\n", [](int i) { return std::string(i == 1 ? " F600 Z-0" : " Z-0"); }),
                       0.01, &s),
            base);
  EXPECT_EQ(weld_whole(quarter("G1 Z-0 F100\n", [](int i) { return std::string(i == 1 ? " Z0 F600" : " Z-0 F600.0"); }),
                       0.01, &s),
            base);
}

TEST(WeldText, AChangedFeedOrZSplitsTheRun) {
  WeldStats s;
  const std::string feed = weld_whole(
      quarter("G1 Z-0 F100\n", [](int i) { return std::string(i == 1 ? " F600" : i >= 10 ? " F700" : ""); }), 0.01,
      &s);
  EXPECT_EQ(s.polylines, 2u);
  EXPECT_NE(feed.find("F700"), std::string::npos) << feed;
  const std::string z =
      weld_whole(quarter("G1 Z-0 F100\n", [](int i) { return std::string(i == 1 ? " F600" : i == 10 ? " Z-1" : ""); }),
                 0.01, &s);
  EXPECT_EQ(s.polylines, 2u);  // the Z move is kept as it is, the runs before and after it welded
  EXPECT_NE(z.find("\nG1 X6.4279 Y7.6604 Z-1\n"), std::string::npos) << z;
}

}  // namespace
