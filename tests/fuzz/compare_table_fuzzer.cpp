// libFuzzer target: any bytes as another tool's table for compare (numeric_table_csv.h), then
// compared with the thesis crank-rocker under the mapping its headers propose
// (table_checks.h says what is checked). Run with tests/fuzz/run-fuzzers.sh.
#include "tests/fuzz/table_checks.h"

#include <unistd.h>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

// One scratch file per process (libFuzzer's -jobs run several side by side), removed at exit.
struct ScratchFile {
  std::string path = "/tmp/linkwright-compare-table-fuzzer-" + std::to_string(getpid()) + ".csv";
  ~ScratchFile() { std::remove(path.c_str()); }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ScratchFile scratch;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  if (const auto finding = linkwright::fuzz::checkCompareTable(bytes, scratch.path)) {
    std::fprintf(stderr, "linkwright compare-table fuzzer: %s\n", finding->c_str());
    std::abort();
  }
  return 0;
}
