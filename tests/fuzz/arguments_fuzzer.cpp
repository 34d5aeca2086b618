// libFuzzer target: any bytes as linkwright-cli's arguments (NUL-separated), through the
// parser and its number parsing, and the cheap commands (fuzz_checks.h says what is checked).
#include "tests/fuzz/fuzz_checks.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  if (const auto finding = linkwright::fuzz::checkArguments(bytes)) {
    std::fprintf(stderr, "linkwright arguments fuzzer: %s\n", finding->c_str());
    std::abort();
  }
  return 0;
}
