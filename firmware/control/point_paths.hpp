// A point file read one path at a time (paths are separated by a truly blank
// line, io/point_file.hpp), for a streamed job (control/job_producer.hpp):
// each path's text is parsed by io::parse_points, its lines numbered as in
// the whole file, so that the points, tols and errors are the whole file's.
// Memory: one path's text and points. Not checked across paths: that every
// path has the same columns as the first (the whole file's parse refuses
// that before anything moves; here a path that differs is read on its own).
#pragma once

#include <cstdio>
#include <string>

#include "io/point_file.hpp"
#include "job/criterion.hpp"

namespace kerf::control {

class PointPaths {
 public:
  enum class Next : std::uint8_t { path, end, error };
  PointPaths() = default;
  ~PointPaths();
  PointPaths(const PointPaths&) = delete;
  PointPaths& operator=(const PointPaths&) = delete;
  // False with "FILE: reason" if it cannot be opened.
  bool open(const std::string& file, job::Criterion criterion, std::string& error);
  // The next path into `one` (file, points, point_lines, tols). After
  // `error`, error() is "FILE:LINE: reason", as read_job's.
  Next next(io::PointFile& one);
  const std::string& error() const { return error_; }
  const std::string& file() const { return file_; }

 private:
  Next fail(std::size_t line, const std::string& reason);
  std::FILE* in_ = nullptr;
  std::string file_, error_, chunk_, line_;
  char* buf_ = nullptr;  // getline's
  std::size_t cap_ = 0;
  job::Criterion criterion_ = job::Criterion::band;
  std::size_t line_no_ = 0, paths_ = 0;
};

}  // namespace kerf::control
