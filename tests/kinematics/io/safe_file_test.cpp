// The one writer (kinematics/io/safe_file.h): a regular file replaced whole, keeping its
// permissions; a full disk (a file-size limit standing in for it, which stops root too) leaves
// the old file as it was; a symlink's target written and the link kept; a FIFO written through,
// not replaced; a folder refused; two writers of one path never mixing their bytes.

#include "kinematics/io/safe_file.h"

#include "tests/support/catch.h"
#include "tests/support/file_size_limit.h"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <new>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

#include <sys/stat.h>

using namespace linkwright::kinematics;
namespace fs = std::filesystem;

namespace {

struct ScratchDir {
  fs::path path;
  ScratchDir() {
    std::random_device random;
    path = fs::temp_directory_path() / ("linkwright-safe-file-" + std::to_string(random()));
    fs::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

std::string contentsOf(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::vector<std::string> namesIn(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST_CASE("a file is written whole, and replaced whole keeping its permissions", "[io][file]") {
  ScratchDir dir;
  const fs::path file = dir.path / "table.csv";
  REQUIRE_FALSE(io::writeFileSafely(file.string(), "first\n"));
  CHECK(contentsOf(file) == "first\n");
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  REQUIRE_FALSE(io::writeFileSafely(file.string(), "second, longer\n"));
  CHECK(contentsOf(file) == "second, longer\n");
  CHECK(fs::status(file).permissions() == (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
  CHECK(namesIn(dir.path) == std::vector<std::string>{"table.csv"});  // no temporary file left
}

TEST_CASE("on a full disk the old file stays as it was and the error says why", "[io][file]") {
  ScratchDir dir;
  const fs::path file = dir.path / "report.pdf";
  REQUIRE_FALSE(io::writeFileSafely(file.string(), "the old report\n"));
  const std::string big(200000, 'x');
  std::optional<Error> error;
  {
    const linkwright::test::FileSizeLimit limit(100000);
    error = io::writeFileSafely(file.string(), big);
  }
  REQUIRE(error);
  CHECK(error->field == "output");
  CHECK_THAT(error->message, Catch::StartsWith("cannot write " + file.string() + ": ") && Catch::Contains("large"));
  CHECK(contentsOf(file) == "the old report\n");
  CHECK(namesIn(dir.path) == std::vector<std::string>{"report.pdf"});
  // A writer that fails part-way through its own file (a library writing by path) too.
  const auto failing = io::writeFileSafely(file.string(), [](const std::string& to) -> std::optional<std::string> {
    std::ofstream(to) << "half";
    return std::string("No space left on device");
  });
  REQUIRE(failing);
  CHECK(failing->message == "cannot write " + file.string() + ": No space left on device");
  CHECK(contentsOf(file) == "the old report\n");
  CHECK(namesIn(dir.path) == std::vector<std::string>{"report.pdf"});
}

TEST_CASE("a streamed file is written whole, and on a full disk, a refusal or out of memory the old one stays",
          "[io][file][stream]") {
  ScratchDir dir;
  const fs::path file = dir.path / "table.csv";
  const auto rows = [](int count) {
    return [count](std::ostream& out) -> std::optional<std::string> {
      for (int i = 0; i < count; ++i) out << i << ",row of a table written as it is solved\n";
      return std::nullopt;
    };
  };
  REQUIRE_FALSE(io::writeStreamSafely(file.string(), rows(3)));
  CHECK(contentsOf(file) ==
        "0,row of a table written as it is solved\n1,row of a table written as it is solved\n"
        "2,row of a table written as it is solved\n");
  // 200 000 rows past a 100 kB limit: the buffer's write fails part-way and says why.
  std::optional<Error> full;
  {
    const linkwright::test::FileSizeLimit limit(100000);
    full = io::writeStreamSafely(file.string(), rows(200000));
  }
  REQUIRE(full);
  CHECK_THAT(full->message, Catch::StartsWith("cannot write " + file.string() + ": ") && Catch::Contains("large"));
  CHECK(contentsOf(file).starts_with("0,row"));
  CHECK(contentsOf(file).size() < 200);
  // The producer's own refusal part-way.
  const auto refused = io::writeStreamSafely(file.string(), [](std::ostream& out) -> std::optional<std::string> {
    out << "half";
    return std::string("--forces: the linkage has no masses");
  });
  REQUIRE(refused);
  CHECK(refused->message == "cannot write " + file.string() + ": --forces: the linkage has no masses");
  // Memory that runs out part-way: the exception goes on, and no temporary file is left.
  CHECK_THROWS_AS(io::writeStreamSafely(file.string(),
                                        [](std::ostream& out) -> std::optional<std::string> {
                                          out << "half";
                                          throw std::bad_alloc();
                                        }),
                  std::bad_alloc);
  CHECK(contentsOf(file).size() < 200);
  CHECK(namesIn(dir.path) == std::vector<std::string>{"table.csv"});
}

TEST_CASE("a symlink's target is written and the link kept", "[io][file]") {
  ScratchDir dir;
  const fs::path target = dir.path / "real.dxf", link = dir.path / "link.dxf";
  REQUIRE_FALSE(io::writeFileSafely(target.string(), "old"));
  fs::create_symlink("real.dxf", link);
  REQUIRE_FALSE(io::writeFileSafely(link.string(), "new"));
  CHECK(fs::is_symlink(link));
  CHECK(contentsOf(target) == "new");
  // A link to a file not there yet makes it.
  fs::create_symlink("later.dxf", dir.path / "dangling.dxf");
  REQUIRE_FALSE(io::writeFileSafely((dir.path / "dangling.dxf").string(), "made"));
  CHECK(fs::is_symlink(dir.path / "dangling.dxf"));
  CHECK(contentsOf(dir.path / "later.dxf") == "made");
}

TEST_CASE("a FIFO or device is written through, never replaced", "[io][file]") {
  ScratchDir dir;
  const fs::path fifo = dir.path / "pipe";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  std::string read;
  std::thread reader([&] { read = contentsOf(fifo); });
  const auto error = io::writeFileSafely(fifo.string(), "through the pipe\n");
  reader.join();
  CHECK_FALSE(error);
  CHECK(read == "through the pipe\n");
  CHECK(fs::is_fifo(fifo));
  // /dev/null takes the bytes and stays the device it is.
  CHECK_FALSE(io::writeFileSafely("/dev/null", "nothing\n"));
  CHECK(fs::is_character_file("/dev/null"));
}

TEST_CASE("a folder, or no name, is refused naming it", "[io][file]") {
  ScratchDir dir;
  const auto folder = io::writeFileSafely(dir.path.string(), "x");
  REQUIRE(folder);
  CHECK(folder->message == "cannot write " + dir.path.string() + ": it is a folder");
  REQUIRE(io::writeFileSafely("", "x"));
  const auto missing = io::writeFileSafely((dir.path / "no" / "such" / "folder.csv").string(), "x");
  REQUIRE(missing);
  CHECK_THAT(missing->message, Catch::Contains("No such file or directory"));
}

TEST_CASE("two writers of one path leave one whole file, never a mix", "[io][file]") {
  ScratchDir dir;
  const fs::path file = dir.path / "shared.csv";
  const std::string a(50000, 'a'), b(70000, 'b');
  std::atomic<int> failures = 0;
  std::thread first([&] {
    for (int i = 0; i < 30; ++i) failures += io::writeFileSafely(file.string(), a).has_value();
  });
  for (int i = 0; i < 30; ++i) failures += io::writeFileSafely(file.string(), b).has_value();
  first.join();
  CHECK(failures == 0);
  const std::string last = contentsOf(file);
  CHECK((last == a || last == b));
  CHECK(namesIn(dir.path) == std::vector<std::string>{"shared.csv"});
}
