#include "job/gcode_part_reader.hpp"

#include <cerrno>
#include <cstring>

#include "io/input_file.hpp"
#include "io/point_file.hpp"

namespace kerf::job {

GcodePartReader::~GcodePartReader() {
  if (in_ != nullptr) std::fclose(in_);
}

bool GcodePartReader::open(const std::string& path, std::size_t part_bytes, std::string& error) {
  name_ = path;
  part_bytes_ = part_bytes < 1 ? 1 : part_bytes;
  in_ = std::fopen(path.c_str(), "rb");
  if (in_ == nullptr) return error = path + ": " + std::strerror(errno), false;
  const std::string problem = io::input_problem(path);
  if (!problem.empty()) return error = path + ": " + problem, false;
  return true;
}

bool GcodePartReader::read_more() {
  const std::size_t have = buf_.size();
  buf_.resize(have + part_bytes_);
  const std::size_t got = std::fread(buf_.data() + have, 1, part_bytes_, in_);
  buf_.resize(have + got);
  eof_ = got < part_bytes_;
  return std::ferror(in_) == 0;
}

// read_gcode ends lines at LF when the file has one anywhere, else at CR.
// A part that has an LF settles it; one with only CRs looks for an LF in the
// rest of the file (an old Mac file is read twice).
bool GcodePartReader::decide_line_ends() {
  if (buf_.find('\n') != std::string::npos) {
    part_.modal.lf_ends = true;
  } else if (buf_.find('\r') != std::string::npos) {
    const long at = std::ftell(in_);
    bool lf = false;
    char chunk[1 << 14];
    for (std::size_t n; !lf && (n = std::fread(chunk, 1, sizeof chunk, in_)) > 0;)
      lf = std::memchr(chunk, '\n', n) != nullptr;
    if (std::ferror(in_) != 0 || std::fseek(in_, at, SEEK_SET) != 0) return false;
    part_.modal.lf_ends = lf;
  } else {
    return true;  // no line end yet
  }
  part_.modal.ends_known = ends_decided_ = true;
  return true;
}

bool GcodePartReader::next(GcodeFile& part, std::string& error) {
  error.clear();
  for (;;) {
    const std::size_t have = buf_.size();  // no line end in these (else they would have been a part)
    if (!eof_ && !read_more()) return error = name_ + ": read error", false;
    if (!ends_decided_ && !decide_line_ends()) return error = name_ + ": read error", false;
    if (buf_.empty() && eof_) return false;
    std::size_t cut = buf_.size();
    if (!eof_) {  // after the last line end read
      const char end = ends_decided_ && !part_.modal.lf_ends ? '\r' : '\n';
      while (cut > have && buf_[cut - 1] != end) --cut;
      if (cut == have) cut = 0;
    }
    if (cut == 0 && buf_.size() <= io::kMaxLineBytes) continue;
    if (cut == 0) cut = buf_.size();  // a line too long: the parse refuses it
    std::string rest = buf_.substr(cut);
    buf_.resize(cut);
    part = parse_gcode_part(std::move(buf_), name_, part_);
    part_.first_line += part.blocks.size();
    buf_ = std::move(rest);
    return true;
  }
}

}  // namespace kerf::job
