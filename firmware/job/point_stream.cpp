#include "job/point_stream.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "io/point_file.hpp"

namespace kerf::job {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// `what` followed by the token in quotes (built by appending: gcc 12 warns
// falsely about the temporaries of a chain of +).
std::string quote(const char* what, const char* begin, const char* end) {
  std::string s(what);
  s += '"';
  s.append(begin, static_cast<std::size_t>(end - begin));
  s += '"';
  return s;
}

}  // namespace

bool PointStream::open(const std::string& path) {
  if (path == "-") {
    in_ = stdin;
    file_ = "<stdin>";
    return true;
  }
  file_ = path;
  in_ = std::fopen(path.c_str(), "r");
  if (in_ == nullptr) {
    reason_ = std::strerror(errno);
    return false;
  }
  owned_ = true;
  return true;
}

PointStream::~PointStream() {
  if (owned_) std::fclose(in_);
}

PointStream::Next PointStream::fail(std::string reason) {
  reason_ = std::move(reason);
  return Next::error;
}

bool PointStream::parse_number(const char* begin, const char* end, double& out) {
  char tok[128];
  const auto len = static_cast<std::size_t>(end - begin);
  if (len >= sizeof tok) {
    reason_ = quote("not a number: ", begin, end);
    return false;
  }
  std::memcpy(tok, begin, len);
  tok[len] = '\0';
  errno = 0;
  char* stop = nullptr;
  const double v = std::strtod(tok, &stop);
  if (stop != tok + len || len == 0) {
    reason_ = quote("not a number: ", begin, end);
    return false;
  }
  if (!std::isfinite(v)) {
    reason_ = errno == ERANGE ? quote("number out of range: ", begin, end)
                              : "NaN or infinite coordinate";
    return false;
  }
  if (std::fabs(v) > io::kMaxCoordinate) {
    reason_ = quote("coordinate out of range: ", begin, end).append(" (the limit is 1e15)");
    return false;
  }
  out = v;
  return true;
}

PointStream::Next PointStream::next(Vec2<double>& p) {
  for (;;) {
    if (std::fgets(buf_, sizeof buf_, in_) == nullptr) {
      if (std::ferror(in_)) return fail(std::string("read error: ") + std::strerror(errno));
      return Next::end;
    }
    ++line_;
    std::size_t len = std::strlen(buf_);
    if (len > 0 && buf_[len - 1] == '\n') {
      --len;
    } else if (!std::feof(in_)) {
      return fail("line longer than 4095 characters");
    }
    const char* hash = static_cast<const char*>(std::memchr(buf_, '#', len));
    const char* end = hash != nullptr ? hash : buf_ + len;
    // Fields separated by blanks or one comma with blanks; two are kept.
    const char* field[2][2];
    int fields = 0;
    const char* c = buf_;
    while (c < end && is_blank(*c)) ++c;
    while (c < end) {
      const char* start = c;
      while (c < end && !is_blank(*c) && *c != ',') ++c;
      if (c == start) return fail("empty field");
      if (fields < 2) {
        field[fields][0] = start;
        field[fields][1] = c;
      }
      ++fields;
      while (c < end && is_blank(*c)) ++c;
      if (c < end && *c == ',') {
        ++c;
        while (c < end && is_blank(*c)) ++c;
        if (c == end) return fail("empty field");
      }
    }
    if (fields == 0) {
      if (hash == nullptr && points_ > 0) blank_after_points_ = true;
      continue;
    }
    if (fields != 2)
      return fail(std::string("expected 2 columns, got ").append(std::to_string(fields))
                      .append(" (--stream fits x y points by the vertex criterion)"));
    if (blank_after_points_)
      return fail("a second path (points after a blank line): --stream fits one path");
    Vec2<double> q;
    if (!parse_number(field[0][0], field[0][1], q.x) || !parse_number(field[1][0], field[1][1], q.y))
      return Next::error;
    if (points_ > 0 && q == last_) {
      ++duplicates_;
      continue;
    }
    last_ = q;
    ++points_;
    p = q;
    return Next::point;
  }
}

}  // namespace kerf::job
