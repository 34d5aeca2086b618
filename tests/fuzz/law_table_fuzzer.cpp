// libFuzzer target: any bytes as a measured motion law's table (law_table_csv.h), for a crank
// and for a linear driver (table_checks.h says what is checked). Run with
// tests/fuzz/run-fuzzers.sh.
#include "tests/fuzz/table_checks.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  if (const auto finding = linkwright::fuzz::checkLawTable(bytes)) {
    std::fprintf(stderr, "linkwright law-table fuzzer: %s\n", finding->c_str());
    std::abort();
  }
  return 0;
}
