#pragma once
// Runs a piece of work in a child process whose address space may grow by only `slack` bytes
// beyond what it holds when it starts (RLIMIT_AS): memory that grows with a job's size fails
// there with std::bad_alloc, as on a machine too small for it. The child's exit code and what
// it wrote to the error stream come back. Not under AddressSanitizer, whose shadow memory
// reserves terabytes of address space (memoryLimitsWork() says whether they apply).

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

namespace linkwright::test {

inline bool memoryLimitsWork() {
#if defined(__SANITIZE_ADDRESS__)
  return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return false;
#else
  return true;
#endif
#else
  return true;
#endif
}

struct LimitedRun {
  int code = -1;  ///< the child's exit code; -1 if it was killed by a signal
  std::string err;
};

// The address space the process holds now, from /proc/self/statm (pages).
inline rlim_t addressSpaceNow() {
  std::ifstream statm("/proc/self/statm");
  unsigned long pages = 0;
  statm >> pages;
  return static_cast<rlim_t>(pages) * static_cast<rlim_t>(sysconf(_SC_PAGESIZE));
}

/// Runs `work` (returning an exit code and filling the error text) in a child limited as above.
inline LimitedRun runWithMemoryLimit(rlim_t slack, const std::function<int(std::string& err)>& work) {
  int pipeEnds[2];
  if (pipe(pipeEnds) != 0) return {};
  const pid_t child = fork();
  if (child == 0) {
    close(pipeEnds[0]);
    const rlimit limit{addressSpaceNow() + slack, addressSpaceNow() + slack};
    setrlimit(RLIMIT_AS, &limit);
    std::string err;
    const int code = work(err);
    (void)!write(pipeEnds[1], err.data(), err.size());
    close(pipeEnds[1]);
    _exit(code);
  }
  close(pipeEnds[1]);
  LimitedRun run;
  char buffer[4096];
  for (ssize_t n; (n = read(pipeEnds[0], buffer, sizeof buffer)) > 0;)
    run.err.append(buffer, static_cast<std::size_t>(n));
  close(pipeEnds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace linkwright::test
