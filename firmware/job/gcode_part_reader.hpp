// A G-code file read in parts of whole lines (job/gcode_reader.hpp's
// parse_gcode_part), each parsed as the whole file's reading would parse
// those lines: the modal state and the line numbers carry from part to part,
// and the file's line end (LF, or CR in a file without one) is decided for
// the whole file before the first part, as read_gcode decides it. The
// window reading (job/program_window.hpp) reads a file twice with it.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

#include "job/gcode_reader.hpp"

namespace kerf::job {

class GcodePartReader {
 public:
  GcodePartReader() = default;
  ~GcodePartReader();
  GcodePartReader(const GcodePartReader&) = delete;
  GcodePartReader& operator=(const GcodePartReader&) = delete;

  // Opens `path` (a file: not stdin, it is read twice); part_bytes: how
  // much is read at a time (a part is its whole lines). False with
  // "FILE: reason", the text read_gcode gives.
  bool open(const std::string& path, std::size_t part_bytes, std::string& error);
  // The next part: false at the end of the file (error empty) or on a read
  // error. A part that does not parse has ok == false (describe_error).
  bool next(GcodeFile& part, std::string& error);
  const std::string& name() const { return name_; }

 private:
  bool read_more();
  bool decide_line_ends();

  std::FILE* in_ = nullptr;
  std::string name_;
  std::size_t part_bytes_ = 0;
  std::string buf_;
  bool eof_ = false, ends_decided_ = false;
  GcodePart part_;
};

}  // namespace kerf::job
