// Reading a point file one line at a time, in memory that does not grow with
// the file: what `kerf fit --stream` needs for inputs of any length. The
// format is io/point_file.hpp's for one path of "x y" lines ('#' comments,
// blanks or one comma between the numbers, CRLF accepted, consecutive
// duplicates dropped and counted); a second path (points after a blank
// line) and extra columns are refused, as are lines over 4095 characters.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

#include "kerf/geom/vec2.hpp"

namespace kerf::job {

class PointStream {
 public:
  enum class Next { point, end, error };

  // Opens `path`, or reads stdin for "-". false (with error()) if it cannot.
  bool open(const std::string& path);
  ~PointStream();

  // The next point, after dropping a repeat of the previous one.
  Next next(Vec2<double>& p);

  const std::string& file() const { return file_; }   // "<stdin>" for "-"
  std::size_t line() const { return line_; }          // of the last point or error
  const std::string& reason() const { return reason_; }
  std::size_t duplicates() const { return duplicates_; }

 private:
  Next fail(std::string reason);
  bool parse_number(const char* begin, const char* end, double& out);

  std::FILE* in_ = nullptr;
  bool owned_ = false;
  std::string file_;
  std::size_t line_ = 0;
  std::string reason_;
  std::size_t duplicates_ = 0;
  std::size_t points_ = 0;
  bool blank_after_points_ = false;
  Vec2<double> last_{};
  char buf_[4096] = {};
};

}  // namespace kerf::job
