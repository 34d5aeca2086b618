#pragma once
// A full disk, as a writer sees it, without a full disk: lowers this process's file-size
// limit (RLIMIT_FSIZE) while alive, so a write past it fails part-way with EFBIG. Unlike
// permission bits it also stops root, who runs the tests in CI. SIGXFSZ, which the kernel
// would send, is ignored meanwhile.

#include "tests/support/catch.h"

#include <sys/resource.h>
#include <csignal>

namespace linkwright::test {

class FileSizeLimit {
public:
  explicit FileSizeLimit(rlim_t bytes) {
    REQUIRE(getrlimit(RLIMIT_FSIZE, &m_saved) == 0);
    m_handler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit lowered = m_saved;
    lowered.rlim_cur = bytes;
    REQUIRE(setrlimit(RLIMIT_FSIZE, &lowered) == 0);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &m_saved);
    std::signal(SIGXFSZ, m_handler);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
  rlimit m_saved{};
  void (*m_handler)(int) = nullptr;
};

}  // namespace linkwright::test
