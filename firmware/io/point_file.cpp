#include "io/point_file.hpp"

#include "io/quote.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace kerf::io {

namespace {

// Indices are 32-bit in core; keep well inside that.
constexpr std::size_t kMaxPoints = std::numeric_limits<std::uint32_t>::max() / 2;

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }


// Splits one line (comment already removed) into its fields. Fields are
// separated by blanks or by one comma with optional blanks around it. Returns
// false for an empty field: a leading, trailing or doubled comma.
bool split_fields(std::string_view line, std::vector<std::string_view>& fields) {
  fields.clear();
  std::size_t i = 0;
  const std::size_t n = line.size();
  while (i < n && is_blank(line[i])) ++i;
  if (i == n) return true;
  for (;;) {
    const std::size_t start = i;
    while (i < n && !is_blank(line[i]) && line[i] != ',') ++i;
    if (i == start) return false;  // a comma where a field should be
    fields.push_back(line.substr(start, i - start));
    while (i < n && is_blank(line[i])) ++i;
    if (i < n && line[i] == ',') {
      ++i;
      while (i < n && is_blank(line[i])) ++i;
      if (i == n) return false;  // trailing comma
    }
    if (i == n) return true;
  }
}

// Parses one coordinate. On failure `reason` says why.
bool parse_number(std::string_view tok, double& out, std::string& reason) {
  const std::string s(tok);  // strtod needs a terminator
  if (s.find('\0') != std::string::npos) {
    reason = "not a number: " + quote(tok);
    return false;
  }
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || end != s.c_str() + s.size()) {
    reason = "not a number: " + quote(tok);
    return false;
  }
  if (!std::isfinite(v)) {  // "nan", "inf", "infinity" and overflow like 1e999
    reason = errno == ERANGE ? "number out of range: " + quote(tok) : "NaN or infinite coordinate";
    return false;
  }
  if (std::fabs(v) > kMaxCoordinate) {
    reason = "coordinate out of range: " + quote(tok) + " (the limit is 1e15)";
    return false;
  }
  out = v;  // an underflow (ERANGE with a tiny value) is accepted as is
  return true;
}

const char* const kLongLine = "line longer than 65536 bytes (not a point file?)";
static_assert(kMaxLineBytes == 65536, "kLongLine names the limit");

PointFile fail(PointFile f, std::size_t line, std::string reason) {
  f.ok = false;
  f.line = line;
  f.reason = std::move(reason);
  f.points.clear();
  f.point_lines.clear();
  f.tols.clear();
  f.tangents.clear();
  f.path_begin.clear();
  return f;
}

// The last path has fewer than two distinct points: named by its number and
// the line of its one point.
PointFile fail_short_path(PointFile f) {
  const std::size_t line = f.point_lines.back();
  std::string reason = "path " + std::to_string(f.path_begin.size()) + " has only one point";
  return fail(std::move(f), line, std::move(reason));
}

}  // namespace

PointFile parse_points(std::string_view text, std::string display_name, bool third_is_angle) {
  PointFile f;
  f.file = std::move(display_name);
  std::vector<std::string_view> fields;
  std::size_t columns = 0;       // 2, 3 or 4, fixed by the first point's line
  std::size_t columns_line = 0;
  bool path_break = false;       // a blank line since the last point
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    ++line_no;
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view line = text.substr(pos, eol - pos);
    pos = eol + 1;
    if (line.size() > kMaxLineBytes) return fail(std::move(f), line_no, kLongLine);
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    if (!split_fields(line, fields)) return fail(std::move(f), line_no, "empty field");
    if (fields.empty()) {
      // Only a truly blank line separates paths; a comment-only line does not.
      if (hash == std::string_view::npos && !f.points.empty()) path_break = true;
      continue;
    }
    if (fields.size() < 2 || fields.size() > 4)
      return fail(std::move(f), line_no,
                  "expected 2, 3 or 4 columns, got " + std::to_string(fields.size()));
    if (columns == 0) {
      columns = fields.size();
      columns_line = line_no;
    } else if (fields.size() != columns) {
      std::string reason = "expected " + std::to_string(columns) + " columns like line " +
                           std::to_string(columns_line) + ", got " + std::to_string(fields.size());
      return fail(std::move(f), line_no, std::move(reason));
    }
    Vec2<double> p;
    std::string reason;
    if (!parse_number(fields[0], p.x, reason) || !parse_number(fields[1], p.y, reason))
      return fail(std::move(f), line_no, reason);
    double tol = 0.0;
    Vec2<double> tangent{};
    const bool has_tol = columns == 3 && !third_is_angle;
    const bool has_tangent = columns == 4 || (columns == 3 && third_is_angle);
    if (has_tol) {
      if (!parse_number(fields[2], tol, reason)) return fail(std::move(f), line_no, "tol: " + reason);
      if (!(tol > 0.0)) return fail(std::move(f), line_no, "tol must be > 0, got " + quote(fields[2]));
    } else if (columns == 3) {
      double deg = 0.0;
      if (!parse_number(fields[2], deg, reason))
        return fail(std::move(f), line_no, "tangent angle: " + reason);
      const double rad = std::fmod(deg, 360.0) * (3.14159265358979323846 / 180.0);
      tangent = {std::cos(rad), std::sin(rad)};
    } else if (columns == 4) {
      if (!parse_number(fields[2], tangent.x, reason) || !parse_number(fields[3], tangent.y, reason))
        return fail(std::move(f), line_no, "tangent: " + reason);
      const double len = std::hypot(tangent.x, tangent.y);
      if (!(len > 0.0) || !std::isfinite(len))
        return fail(std::move(f), line_no, "tangent must not be zero");
      tangent = tangent * (1.0 / len);
    }
    if (path_break) {
      path_break = false;
      if (f.points.size() - f.path_begin.back() < 2) return fail_short_path(std::move(f));
      f.path_begin.push_back(f.points.size());
    } else if (!f.points.empty() && f.points.back() == p) {
      ++f.duplicates_dropped;
      if (has_tol) f.tols.back() = std::fmin(f.tols.back(), tol);  // the stricter one
      continue;  // (a duplicate keeps the first one's tangent)
    }
    if (f.points.size() >= kMaxPoints) return fail(std::move(f), line_no, "too many points");
    if (f.points.empty()) f.path_begin.push_back(0);
    f.points.push_back(p);
    f.point_lines.push_back(line_no);
    if (has_tol) f.tols.push_back(tol);
    if (has_tangent) f.tangents.push_back(tangent);
  }
  if (f.points.size() < 2) {
    // (the reason first: arguments are evaluated in no fixed order, and fail() empties f)
    std::string reason = "fewer than two distinct points (got " + std::to_string(f.points.size()) + ")";
    return fail(std::move(f), 0, std::move(reason));
  }
  if (f.points.size() - f.path_begin.back() < 2) return fail_short_path(std::move(f));
  f.ok = true;
  return f;
}

PointFile read_points(const std::string& path, bool third_is_angle) {
  const bool use_stdin = path == "-";
  std::string name = use_stdin ? "<stdin>" : path;
  std::FILE* in = use_stdin ? stdin : std::fopen(path.c_str(), "rb");
  if (in == nullptr) {
    const int err = errno;
    PointFile f;
    f.file = std::move(name);
    return fail(std::move(f), 0, std::string("cannot open: ") + std::strerror(err));
  }
  std::string text;
  char buf[65536];
  std::size_t got;
  // Reading stops inside a line longer than kMaxLineBytes; the parser reports
  // it (or an error on an earlier line) from what was read.
  std::size_t line_bytes = 0;
  bool too_long = false;
  while (!too_long && (got = std::fread(buf, 1, sizeof buf, in)) > 0) {
    for (std::size_t k = 0; k < got; ++k) {
      if (buf[k] == '\n') {
        line_bytes = 0;
      } else if (++line_bytes > kMaxLineBytes) {
        too_long = true;  // stop reading: the rest is not looked at
        break;
      }
    }
    text.append(buf, got);
  }
  const bool read_failed = std::ferror(in) != 0;
  const int err = errno;
  if (!use_stdin) std::fclose(in);
  if (read_failed) {
    PointFile f;
    f.file = std::move(name);
    return fail(std::move(f), 0, std::string("cannot read: ") + std::strerror(err));
  }
  return parse_points(text, std::move(name), third_is_angle);
}

std::string describe_error(const PointFile& f) {
  // (appended piecewise: "x" + std::string trips a GCC 12 -Wrestrict false positive)
  std::string s = f.file;
  if (f.line != 0) {
    s += ':';
    s += std::to_string(f.line);
  }
  s += ": ";
  s += f.reason;
  return s;
}

}  // namespace kerf::io
