// The one reader (kinematics/io/bounded_read.h): a regular file read whole; past its limit
// refused as it reads; /dev/zero, a FIFO and a folder refused before reading (they could be
// endless); a missing file named with the system's reason.

#include "kinematics/io/bounded_read.h"

#include "tests/support/catch.h"

#include <filesystem>
#include <fstream>
#include <random>

#include <sys/stat.h>

using namespace linkwright::kinematics;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  std::random_device random;
  const fs::path dir = fs::temp_directory_path() / ("linkwright-read-" + std::to_string(random()));
  fs::create_directories(dir);
  return dir / name;
}

}  // namespace

TEST_CASE("a regular file is read whole, and refused past its limit", "[io][file]") {
  const fs::path file = scratch("table.csv");
  std::ofstream(file, std::ios::binary) << "0,1\n1,2\n";
  const auto text = io::readFileBounded(file.string(), 1u << 20, "a table");
  REQUIRE(text);
  CHECK(*text == "0,1\n1,2\n");
  std::ofstream(file, std::ios::binary) << std::string((2u << 20) + 5, 'x');
  const auto big = io::readFileBounded(file.string(), 2u << 20, "a table");
  REQUIRE_FALSE(big);
  CHECK(big.error().field == "file");
  CHECK(big.error().message == file.string() + ": is larger than 2 MiB, more than a table can be");
  fs::remove_all(file.parent_path());
}

TEST_CASE("devices, FIFOs and folders are refused before reading, a missing file named", "[io][file]") {
  // /dev/zero never ends: it grew a reader's memory by 0.7 GB/s until the kernel killed it.
  const auto zero = io::readFileBounded("/dev/zero", io::kMaxDocumentBytes, "a Linkwright document");
  REQUIRE_FALSE(zero);
  CHECK(zero.error().message ==
        "/dev/zero: cannot be read as a Linkwright document: it is not a regular file (a regular file of at most "
        "16 MiB)");
  const fs::path fifo = scratch("pipe");
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  const auto pipe = io::readFileBounded(fifo.string(), 1u << 20, "a table");  // does not wait for a writer
  REQUIRE_FALSE(pipe);
  CHECK_THAT(pipe.error().message, Catch::Contains("it is not a regular file"));
  const auto folder = io::readFileBounded(fifo.parent_path().string(), 1u << 20, "a table");
  REQUIRE_FALSE(folder);
  CHECK_THAT(folder.error().message, Catch::Contains("it is a folder"));
  const auto missing = io::readFileBounded((fifo.parent_path() / "none.csv").string(), 1u << 20, "a table");
  REQUIRE_FALSE(missing);
  CHECK_THAT(missing.error().message,
             Catch::EndsWith("none.csv: cannot be opened for reading: No such file or directory"));
  fs::remove_all(fifo.parent_path());
}
