#include "io/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace kerf::io {

std::string input_problem(const std::string& path) {
  if (path == "-") return {};
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) return std::string("cannot open: ") + std::strerror(errno);
  std::string why;
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    why = std::string("cannot read: ") + std::strerror(errno);
  } else if (S_ISDIR(st.st_mode)) {
    why = "is a directory";
  } else if (S_ISREG(st.st_mode)) {
    // Permissions do not stop root; a read does fail on a file whose
    // contents the kernel cannot give (EIO), and that is what matters.
    char byte = 0;
    if (::pread(fd, &byte, 1, 0) < 0) why = std::string("cannot read: ") + std::strerror(errno);
  }
  ::close(fd);
  return why;
}

bool input_readable(const std::string& path) {
  if (path.empty()) return true;
  const std::string why = input_problem(path);
  if (why.empty()) return true;
  std::fprintf(stderr, "%s: %s\n", path.c_str(), why.c_str());
  return false;
}

}  // namespace kerf::io
