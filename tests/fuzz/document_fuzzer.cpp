// libFuzzer target: any bytes as a Linkwright document, through the CLI's commands
// (fuzz_checks.h says what is checked). Run with tests/fuzz/run-fuzzers.sh.
#include "tests/fuzz/fuzz_checks.h"

#include <unistd.h>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

// One scratch file per process (libFuzzer's -jobs run several side by side), removed at exit.
struct ScratchFile {
  std::string path = "/tmp/linkwright-document-fuzzer-" + std::to_string(getpid()) + ".linkwright";
  ~ScratchFile() { std::remove(path.c_str()); }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ScratchFile scratchFile;
  const std::string& scratch = scratchFile.path;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  if (const auto finding = linkwright::fuzz::checkDocument(bytes, scratch)) {
    std::fprintf(stderr, "linkwright document fuzzer: %s\n", finding->c_str());
    std::abort();
  }
  return 0;
}
