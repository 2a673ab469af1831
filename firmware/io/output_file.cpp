#include "io/output_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>

namespace kerf::io {

namespace {

bool write_stream(std::FILE* f, const std::string& text) {
  const std::size_t n = std::fwrite(text.data(), 1, text.size(), f);
  return std::fflush(f) == 0 && n == text.size() && std::ferror(f) == 0;
}

}  // namespace

bool write_output(const std::string& path, const std::string& text) {
  if (path == "-") return write_stream(stdout, text);
  struct stat st {};
  const bool exists = ::stat(path.c_str(), &st) == 0;
  if (exists && !S_ISREG(st.st_mode)) {  // a device or fifo: write in place, never replace it
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) return false;
    const bool ok = write_stream(f, text);
    const int why = errno;
    return std::fclose(f) == 0 && ok ? true : (errno = why, false);
  }
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) return false;
  bool ok = write_stream(f, text);
  int why = errno;
  if (std::fclose(f) != 0 && ok) {
    ok = false;
    why = errno;
  }
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) {
    ok = false;
    why = errno;
  }
  if (!ok) {
    std::remove(tmp.c_str());
    errno = why;
  }
  return ok;
}

}  // namespace kerf::io
