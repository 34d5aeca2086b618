#include "kinematics/io/safe_file.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace linkwright::kinematics::io {
namespace {

namespace fs = std::filesystem;

std::string reason(int error) { return std::strerror(error != 0 ? error : EIO); }

// The file a path names: a symbolic link followed (a chain too) to what it points at, which
// may not exist yet.
std::optional<fs::path> resolveLinks(const fs::path& path, std::string& why) {
  fs::path at = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (lstat(at.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return at;
    std::error_code ec;
    const fs::path link = fs::read_symlink(at, ec);
    if (ec) {
      why = ec.message();
      return std::nullopt;
    }
    at = link.is_absolute() ? link : at.parent_path() / link;
  }
  why = reason(ELOOP);
  return std::nullopt;
}

// A new file beside `target` with a name no other writer uses, created with `mode`.
int createTemporary(const fs::path& target, mode_t mode, std::string& name) {
  static std::atomic<unsigned> counter{0};
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  for (int attempt = 0; attempt < 100; ++attempt) {
    name = (folder / (target.filename().string() + ".linkwright-tmp." + std::to_string(getpid()) + "." +
                      std::to_string(counter++)))
               .string();
    const int fd = open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

// `contents` into the file at `path`, truncated: each write and the close checked.
std::optional<std::string> writeWholeFile(const std::string& path, std::string_view contents) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) return reason(errno);
  std::size_t done = 0;
  while (done < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + done, contents.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      close(fd);
      return reason(error);
    }
    done += static_cast<std::size_t>(n);
  }
  if (close(fd) != 0) return reason(errno);
  return std::nullopt;
}

}  // namespace

Error outputError(const std::string& path, const std::string& why) {
  return Error{ErrorCode::InvalidValue, "output", "cannot write " + path + ": " + why};
}

std::optional<Error> writeFileSafely(const std::string& path, std::string_view contents) {
  return writeFileSafely(path, [contents](const std::string& to) { return writeWholeFile(to, contents); });
}

std::optional<Error> writeFileSafely(const std::string& path, const FileWriter& write) {
  if (path.empty()) return outputError(path, "no file name given");
  std::string why;
  const auto target = resolveLinks(path, why);
  if (!target) return outputError(path, why);
  struct stat st {};
  const bool exists = stat(target->c_str(), &st) == 0;
  if (exists && S_ISDIR(st.st_mode)) return outputError(path, "it is a folder");
  // A device, FIFO or terminal is written through: replacing /dev/null would break the system.
  if (exists && !S_ISREG(st.st_mode)) {
    if (auto failed = write(target->string())) return outputError(path, *failed);
    return std::nullopt;
  }
  std::string temp;
  // A replaced file keeps its permissions; a new one gets the umask's.
  const int fd = createTemporary(*target, exists ? (st.st_mode & 07777) : 0666, temp);
  if (fd < 0) return outputError(path, reason(errno));
  if (exists) fchmod(fd, st.st_mode & 07777);  // the umask narrowed what open() gave it
  close(fd);
  const auto fail = [&](const std::string& message) {
    unlink(temp.c_str());
    return outputError(path, message);
  };
  if (auto failed = write(temp)) return fail(*failed);
  // On disk before it replaces the old file: a crash then leaves one or the other, whole.
  const int sync = open(temp.c_str(), O_RDONLY | O_CLOEXEC);
  if (sync < 0 || fsync(sync) != 0) {
    const int error = errno;
    if (sync >= 0) close(sync);
    return fail(reason(error));
  }
  close(sync);
  if (rename(temp.c_str(), target->c_str()) != 0) return fail(reason(errno));
  return std::nullopt;
}

}  // namespace linkwright::kinematics::io
