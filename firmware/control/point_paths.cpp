#include "control/point_paths.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <sys/types.h>

namespace kerf::control {

namespace {

// Whether a line (without its newline) is truly blank, and whether it holds a point.
bool blank(const std::string& line) {
  for (char c : line)
    if (c != ' ' && c != '\t' && c != '\r' && c != '\v' && c != '\f') return false;
  return true;
}
bool has_point(const std::string& line) {
  for (char c : line) {
    if (c == '#') return false;
    if (c != ' ' && c != '\t' && c != '\r' && c != '\v' && c != '\f') return true;
  }
  return false;
}

}  // namespace

PointPaths::~PointPaths() {
  if (in_ != nullptr) std::fclose(in_);
  std::free(buf_);
}

bool PointPaths::open(const std::string& file, job::Criterion criterion, std::string& error) {
  file_ = file;
  criterion_ = criterion;
  in_ = std::fopen(file.c_str(), "rb");
  if (in_ == nullptr) {
    error = file + ": cannot open: " + std::strerror(errno);
    return false;
  }
  return true;
}

PointPaths::Next PointPaths::fail(std::size_t line, const std::string& reason) {
  error_ = line > 0 ? file_ + ":" + std::to_string(line) + ": " + reason : file_ + ": " + reason;
  return Next::error;
}

PointPaths::Next PointPaths::next(io::PointFile& one) {
  chunk_.clear();
  std::size_t first_line = line_no_ + 1, point_line = 0;
  bool points = false;
  for (;;) {
    const ssize_t got = ::getline(&buf_, &cap_, in_);
    if (got < 0) break;
    line_.assign(buf_, static_cast<std::size_t>(got));
    if (!line_.empty() && line_.back() == '\n') line_.pop_back();
    ++line_no_;
    if (points && blank(line_)) break;  // the path's end (the blank line is not part of the next)
    if (!points && has_point(line_)) point_line = line_no_;
    points = points || has_point(line_);
    chunk_ += line_;
    chunk_ += '\n';
  }
  if (std::ferror(in_)) return fail(0, std::string("cannot read: ") + std::strerror(errno));
  if (!points) {
    if (paths_ == 0) return fail(0, "fewer than two distinct points (got 0)");
    return Next::end;
  }
  ++paths_;
  one = io::parse_points(chunk_, file_);
  const std::size_t offset = first_line - 1;
  if (!one.ok) {
    if (one.line == 0 && one.reason.rfind("fewer than two distinct points", 0) == 0)
      return fail(point_line, "path " + std::to_string(paths_) + " has only one point");
    return fail(one.line > 0 ? one.line + offset : 0, one.reason);
  }
  for (std::size_t& l : one.point_lines) l += offset;
  one.path_begin = {0};
  if (!one.tols.empty() && criterion_ != job::Criterion::band)
    return fail(one.point_lines.front(), "a third column (per-point tol) needs --criterion band");
  if (!one.tangents.empty())
    return fail(one.point_lines.front(), criterion_ != job::Criterion::biarc
                                             ? "tangent columns (x y tx ty) need --criterion biarc"
                                             : "tangent columns are read by kerf fit only (this command estimates them)");
  return Next::path;
}

}  // namespace kerf::control
