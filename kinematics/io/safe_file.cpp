#include "kinematics/io/safe_file.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <streambuf>

#include <climits>
#include <csignal>

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

// The temporary files being written, for the signal handler: a fixed table of C strings, each
// slot claimed by one writer (Free → Filling), its name copied, then Pending until the file is
// renamed or removed. The handler reads only Pending slots, through lock-free atomics.
constexpr int kFree = 0, kFilling = 1, kPending = 2;
struct PendingSlot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX]{};
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots' states");
constexpr std::size_t kPendingSlots = 32;
std::array<PendingSlot, kPendingSlots> pendingSlots;

extern "C" void removePendingAndReraise(int sig) {
  for (PendingSlot& slot : pendingSlots)
    if (slot.state.load(std::memory_order_acquire) == kPending) unlink(slot.path);
  // SA_RESETHAND made the disposition the default again; the signal is blocked until the
  // handler returns, then ends the process as if no handler had been installed.
  raise(sig);
}

// One temporary file's slot while it may exist: the name is registered before the file is
// created (a signal in between finds no file to remove) and released once it is renamed or
// removed. With every slot taken (32 writes at once) the file is written unregistered.
class PendingTemporary {
public:
  PendingTemporary() {
    for (PendingSlot& slot : pendingSlots) {
      int free = kFree;
      if (slot.state.compare_exchange_strong(free, kFilling, std::memory_order_acq_rel)) {
        m_slot = &slot;
        return;
      }
    }
  }
  PendingTemporary(const PendingTemporary&) = delete;
  PendingTemporary& operator=(const PendingTemporary&) = delete;
  ~PendingTemporary() { release(); }
  // `name` is the file about to be created (or the next one tried).
  void set(const std::string& name) {
    if (m_slot == nullptr) return;
    m_slot->state.store(kFilling, std::memory_order_release);
    if (name.size() >= sizeof m_slot->path) return;  // too long for the table: not removed on a signal
    std::memcpy(m_slot->path, name.c_str(), name.size() + 1);
    m_slot->state.store(kPending, std::memory_order_release);
  }
  void release() {
    if (m_slot != nullptr) m_slot->state.store(kFree, std::memory_order_release);
    m_slot = nullptr;
  }

private:
  PendingSlot* m_slot = nullptr;
};

// A new file beside `target` with a name no other writer uses, created with `mode`; its name
// registered in `pending` first.
int createTemporary(const fs::path& target, mode_t mode, std::string& name, PendingTemporary& pending) {
  static std::atomic<unsigned> counter{0};
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  for (int attempt = 0; attempt < 100; ++attempt) {
    name = (folder / (target.filename().string() + ".linkwright-tmp." + std::to_string(getpid()) + "." +
                      std::to_string(counter++)))
               .string();
    pending.set(name);
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

// A stream buffer over a file descriptor that keeps the first write error: std::ofstream
// reports only that something failed, and its close is not checked at all.
class CheckedFileBuffer : public std::streambuf {
public:
  explicit CheckedFileBuffer(int fd) : m_fd(fd) { setp(m_buffer.data(), m_buffer.data() + m_buffer.size()); }
  // The reason writing failed, if it did.
  std::optional<std::string> failure() const {
    return m_error != 0 ? std::optional<std::string>(reason(m_error)) : std::nullopt;
  }

protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

private:
  bool drain() {
    const char* at = pbase();
    while (m_error == 0 && at < pptr()) {
      const ssize_t n = ::write(m_fd, at, static_cast<std::size_t>(pptr() - at));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) m_error = n < 0 ? errno : ENOSPC;
      else at += n;
    }
    setp(m_buffer.data(), m_buffer.data() + m_buffer.size());
    return m_error == 0;
  }

  int m_fd;
  int m_error = 0;
  std::array<char, 1 << 16> m_buffer{};
};

// The file at `path`, truncated, written by `write` through a checked buffer, then closed.
std::optional<std::string> writeWholeStream(const std::string& path, const StreamWriter& write) {
  const int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) return reason(errno);
  CheckedFileBuffer buffer(fd);
  std::ostream out(&buffer);
  auto stopped = write(out);
  out.flush();
  const auto failed = buffer.failure();
  const bool closed = close(fd) == 0;
  const int closeError = errno;
  if (stopped) return stopped;
  if (failed) return failed;
  if (!closed) return reason(closeError);
  return std::nullopt;
}

}  // namespace

void removeTemporaryFilesOnSignals() {
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current {};
    if (sigaction(sig, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
    struct sigaction removing {};
    removing.sa_handler = removePendingAndReraise;
    removing.sa_flags = SA_RESETHAND;
    sigemptyset(&removing.sa_mask);
    for (const int other : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&removing.sa_mask, other);
    sigaction(sig, &removing, nullptr);
  }
}

Error outputError(const std::string& path, const std::string& why) {
  return Error{ErrorCode::InvalidValue, "output", "cannot write " + path + ": " + why};
}

std::optional<Error> writeFileSafely(const std::string& path, std::string_view contents) {
  return writeFileSafely(path, [contents](const std::string& to) { return writeWholeFile(to, contents); });
}

std::optional<Error> writeStreamSafely(const std::string& path, const StreamWriter& write) {
  return writeFileSafely(path, [&write](const std::string& to) { return writeWholeStream(to, write); });
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
  PendingTemporary pending;
  // A replaced file keeps its permissions; a new one gets the umask's.
  const int fd = createTemporary(*target, exists ? (st.st_mode & 07777) : 0666, temp, pending);
  if (fd < 0) return outputError(path, reason(errno));
  if (exists) fchmod(fd, st.st_mode & 07777);  // the umask narrowed what open() gave it
  close(fd);
  const auto fail = [&](const std::string& message) {
    unlink(temp.c_str());
    return outputError(path, message);
  };
  std::optional<std::string> failed;
  try {
    failed = write(temp);
  } catch (...) {
    unlink(temp.c_str());  // out of memory part-way, say: the old file stays, no temporary is left
    throw;
  }
  if (failed) return fail(*failed);
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
