// kerf weld streaming (weld/weld.hpp: weld_stream): the file is read in
// parts of whole lines; each part is parsed, welded and written before the
// next is read, so memory does not grow with the file.
#include <algorithm>
#include <cstdio>
#include <string>

#include "io/point_file.hpp"
#include "io/prefault.hpp"
#include "job/gcode_reader.hpp"
#include "weld/weld.hpp"

namespace kerf::weld {

namespace {

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

// Where the last whole line of buf ends (0: none yet). After the last '\n';
// in a file without one (CR only), after the last '\r' that is not buf's last
// byte (a '\n' may follow it in the next read).
std::size_t last_line_end(const std::string& buf) {
  const std::size_t nl = buf.rfind('\n');
  if (nl != std::string::npos) return nl + 1;
  if (buf.size() < 2) return 0;
  const std::size_t cr = buf.rfind('\r', buf.size() - 2);
  return cr == std::string::npos ? 0 : cr + 1;
}

// Appends up to n bytes of in to buf; false on a read error.
bool read_more(std::FILE* in, std::string& buf, std::size_t n, bool& eof) {
  const std::size_t have = buf.size();
  if (buf.capacity() < have + n) buf.reserve(have + n);
  io::prefault(buf.data() + have, n);  // one call instead of a page fault per 4 KiB
  buf.resize(have + n);
  const std::size_t got = std::fread(buf.data() + have, 1, n, in);
  buf.resize(have + got);
  eof = got < n;
  return std::ferror(in) == 0;
}

}  // namespace

bool scan_gcode(std::FILE* in, const std::string& name, std::size_t chunk_bytes, GcodeScan& scan,
                std::string& error) {
  scan = GcodeScan{};
  std::string buf;
  job::GcodePart part;
  bool eof = false;
  while (!eof) {
    if (!read_more(in, buf, chunk_bytes, eof)) return error = name + ": read error", false;
    std::size_t cut = eof ? buf.size() : last_line_end(buf);
    if (cut == 0 && buf.size() <= io::kMaxLineBytes) continue;
    if (cut == 0) cut = buf.size();  // a line too long: the parse refuses it
    const job::GcodeFile g = job::parse_gcode_part(buf.substr(0, cut), name, part);
    if (!g.ok) return error = job::describe_error(g), false;
    scan.decimals = std::max(scan.decimals, g.decimals);
    scan.lines += g.blocks.size();
    part.first_line += g.blocks.size();
    buf.erase(0, cut);
  }
  return true;
}

StreamEnd weld_stream(std::FILE* in, const std::string& name, const Sink& sink, const WeldOptions& opts,
                      const StreamOptions& so, WeldStats& stats, std::string& error) {
  stats = WeldStats{};
  std::string buf, out;
  Welder welder(opts, opts.decimals >= 0 ? opts.decimals : 3, stats, out);
  std::size_t decimals = 0;  // the most seen so far
  job::GcodePart part;
  bool eof = false;
  for (;;) {
    if (!eof && !read_more(in, buf, so.chunk_bytes, eof)) return error = name + ": read error", StreamEnd::bad_input;
    std::size_t cut = eof ? buf.size() : last_line_end(buf);
    if (cut == 0 && !eof && buf.size() <= io::kMaxLineBytes) continue;
    if (cut == 0) cut = buf.size();  // a line too long: the parse refuses it
    const std::size_t first_line = part.first_line;
    const bool last = eof && cut == buf.size();
    // The part's text moves into the parse (copying it cost small files a
    // page fault per 4 KiB); what follows it, a piece of a line, is kept.
    std::string rest = buf.substr(cut);
    buf.resize(cut);
    const job::GcodeFile g = job::parse_gcode_part(std::move(buf), name, part);
    if (!g.ok) return error = job::describe_error(g), StreamEnd::bad_input;
    std::size_t end = g.blocks.size();
    if (!last && part.run_block != kNone) {
      if (end - part.run_block <= so.window_lines) end = part.run_block;  // read again with what follows
      else ++stats.forced_commits;  // the run is cut here; the next part starts another
    }
    if (opts.decimals < 0) {
      decimals = std::max(decimals, g.decimals);
      welder.set_decimals(std::max<int>(3, static_cast<int>(decimals)));
    }
    out.clear();
    if (out.capacity() < cut + cut / 8) out.reserve(cut + cut / 8);  // arcs shorten it, a "G1 " lengthens it
    io::prefault(out.data(), cut);
    if (!welder.add(g, end, error)) return StreamEnd::fit_failed;
    if (!out.empty() && !sink(out)) return error = "cannot write the output", StreamEnd::write_failed;
    stats.lines += end;
    if (last) break;
    const std::string& text = g.source->text;
    const std::size_t consumed =
        end < g.blocks.size() ? static_cast<std::size_t>(g.blocks[end].text.data() - text.data()) : cut;
    buf.assign(text, consumed);
    buf += rest;
    part.first_line = first_line + end;
    if (end < g.blocks.size()) part.modal = part.at_run;
  }
  return StreamEnd::ok;
}

}  // namespace kerf::weld
