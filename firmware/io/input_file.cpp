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
  // stat first: opening a named pipe would let its writer start into a pipe
  // that this check then closes.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::string("cannot open: ") + std::strerror(errno);
  if (S_ISDIR(st.st_mode)) return "is a directory";
  if (!S_ISREG(st.st_mode)) return {};  // a pipe or a device: its reader reports
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::string("cannot open: ") + std::strerror(errno);
  // Permissions do not stop root; a read does fail on a file whose contents
  // the kernel cannot give (EIO), and that is what matters.
  char byte = 0;
  std::string why;
  if (::pread(fd, &byte, 1, 0) < 0) why = std::string("cannot read: ") + std::strerror(errno);
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
