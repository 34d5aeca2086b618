#include "kinematics/io/bounded_read.h"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace linkwright::kinematics::io {
namespace {

std::string mebibytes(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

}  // namespace

Result<std::string> readFileBounded(const std::string& path, std::size_t limit, const std::string& what) {
  const auto refuse = [&](const std::string& why) { return Error{ErrorCode::InvalidValue, "file", path + ": " + why}; };
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);  // a FIFO must not block the open
  if (fd < 0) return refuse(std::string("cannot be opened for reading: ") + std::strerror(errno));
  struct stat st {};
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    close(fd);
    return refuse(std::string("cannot be read as ") + what + ": " +
                  (S_ISDIR(st.st_mode) ? "it is a folder" : "it is not a regular file") +
                  " (a regular file of at most " + mebibytes(limit) + ")");
  }
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      close(fd);
      return refuse(std::string("cannot be read: ") + std::strerror(error));
    }
    if (n == 0) break;
    // Stopped as it passes the limit, however large the file says it is or grows to be.
    if (text.size() + static_cast<std::size_t>(n) > limit) {
      close(fd);
      return refuse("is larger than " + mebibytes(limit) + ", more than " + what + " can be");
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
  close(fd);
  return text;
}

}  // namespace linkwright::kinematics::io
