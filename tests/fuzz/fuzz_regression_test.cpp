// Every stored fuzz input, the seed corpus and the findings kept as regressions, runs through
// the fuzzers' checks in the ordinary test suite; and the checks themselves catch what they
// are there to catch.

#include "tests/fuzz/fuzz_checks.h"
#include "tests/fuzz/table_checks.h"

#include "tests/support/catch.h"

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace linkwright;
namespace fs = std::filesystem;

namespace {

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The files of tests/fuzz/corpus/<kind> and tests/fuzz/regressions/<kind>.
std::vector<fs::path> storedInputs(const std::string& kind) {
  std::vector<fs::path> files;
  for (const char* folder : {"corpus", "regressions"}) {
    const fs::path dir = fs::path(LINKWRIGHT_FUZZ_INPUTS) / folder / kind;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_CASE("nonFiniteToken finds nan and inf written as numbers, and only those", "[fuzz]") {
  CHECK(fuzz::nonFiniteToken("crank_angle_deg,x\n0,-nan\n") == "-nan");
  CHECK(fuzz::nonFiniteToken("B_ax_mm_s2 = inf") == "inf");
  CHECK(fuzz::nonFiniteToken("max +INF at 3") == "+INF");
  CHECK(fuzz::nonFiniteToken("(got nan(0x8000))") == "nan");
  // What the user typed may be quoted back: "--speed must be finite (got 'nan')".
  CHECK_FALSE(fuzz::nonFiniteToken("--speed must be positive and finite (got 'nan')", "arm\n--speed\nnan"));
  CHECK(fuzz::nonFiniteToken("x = inf", "arm\n--speed\nnan") == "inf");
  CHECK_FALSE(fuzz::nonFiniteToken("ideal mechanical advantage infinite at a toggle"));
  CHECK_FALSE(fuzz::nonFiniteToken("I13 at infinity, direction 90°; 1.5e308, info"));
  CHECK_FALSE(fuzz::nonFiniteToken("finance,nano,inflow"));
}

TEST_CASE("splitArguments cuts at NUL and bounds what an input can ask for", "[fuzz]") {
  using namespace std::string_literals;
  CHECK(fuzz::splitArguments("classify\0--fourbar\0"s
                             "60,25,70,45"s) == std::vector<std::string>{"classify", "--fourbar", "60,25,70,45"});
  CHECK(fuzz::splitArguments("") == std::vector<std::string>{""});
  CHECK(fuzz::splitArguments(std::string(100, '\0')).size() == 32);
  CHECK(fuzz::splitArguments(std::string(1000, 'x')).front().size() == 256);
}

TEST_CASE("the argument checks flag what they must", "[fuzz]") {
  using namespace std::string_literals;
  CHECK_FALSE(fuzz::checkArguments("classify\0--example\0thesis-crank-rocker"s));
  CHECK_FALSE(fuzz::checkArguments("analyze\0--fourbar\0-1,2,3,4"s));  // an error, clearly given
}

TEST_CASE("the arguments fuzzer runs only what finishes at once", "[fuzz]") {
  const auto cheap = [](std::vector<std::string> args) {
    const auto parsed = cli::parseArguments(args);
    REQUIRE(parsed);
    return fuzz::isCheapToRun(*parsed);
  };
  CHECK(cheap({"analyze", "--example", "thesis-crank-rocker"}));
  CHECK(cheap({"extremes", "--fourbar", "60,25,70,45", "--samples", "4000"}));
  CHECK(cheap({"analyze", "--fourbar", "60,25,70,45", "--to", "-1"}));  // refused before the sweep
  CHECK(cheap({"classify", "--fourbar", "60,25,70,45"}));
  // The CI's finding: a range the CLI accepts, a million rows at the default 1°.
  CHECK_FALSE(cheap({"analyze", "--example", "thesis-crank-rocker", "--to", "999999"}));
  CHECK_FALSE(cheap({"extremes", "--fourbar", "60,25,70,45", "--samples", "4001"}));
  CHECK_FALSE(cheap({"analyze", "--example", "thesis-crank-rocker", "--law", "constant", "--step-time", "1e-6"}));
  CHECK_FALSE(cheap({"analyze", "--example", "thesis-crank-rocker", "-o", "out.csv"}));
  CHECK_FALSE(cheap({"synthesize", "swing", "--swing", "60", "--time-ratio", "1.3", "--rocker", "50"}));
}

TEST_CASE("every stored document input gives an error or finite results", "[fuzz]") {
  const auto files = storedInputs("documents");
  REQUIRE(files.size() >= 10);  // the seed corpus: one document per built-in example at least
  const std::string scratch = (fs::temp_directory_path() / "linkwright-fuzz-regression.linkwright").string();
  for (const auto& file : files) {
    INFO(file.filename().string());
    CHECK(fuzz::checkDocument(readBytes(file), scratch).value_or("no finding") == "no finding");
  }
  fs::remove(scratch);
}

TEST_CASE("every stored argument input gives an error or finite results", "[fuzz]") {
  const auto files = storedInputs("arguments");
  REQUIRE(files.size() >= 10);  // the seed corpus: the golden CLI cases' arguments
  for (const auto& file : files) {
    INFO(file.filename().string());
    CHECK(fuzz::checkArguments(readBytes(file)).value_or("no finding") == "no finding");
  }
}

TEST_CASE("every stored compare table gives an error or a table that keeps its layout", "[fuzz]") {
  const auto files = storedInputs("compare-tables");
  REQUIRE(files.size() >= 5);  // the seed corpus: the thesis's tables, analyze's own, a decimal comma
  const std::string scratch = (fs::temp_directory_path() / "linkwright-fuzz-regression.csv").string();
  for (const auto& file : files) {
    INFO(file.filename().string());
    CHECK(fuzz::checkCompareTable(readBytes(file), scratch).value_or("no finding") == "no finding");
  }
  fs::remove(scratch);
}

TEST_CASE("every stored law table gives an error or a finite law", "[fuzz]") {
  const auto files = storedInputs("law-tables");
  REQUIRE(files.size() >= 5);  // the seed corpus: degrees, radians, lengths, a byte-order mark, too few rows
  for (const auto& file : files) {
    INFO(file.filename().string());
    CHECK(fuzz::checkLawTable(readBytes(file)).value_or("no finding") == "no finding");
  }
}

TEST_CASE("the table checks pass a good table, a clear refusal and a nan the table holds", "[fuzz]") {
  const std::string scratch = (fs::temp_directory_path() / "linkwright-fuzz-table-checks.csv").string();
  CHECK_FALSE(fuzz::checkCompareTable("theta2 (deg),theta4 (deg)\n0,58.41\n90,45\n", scratch));
  CHECK_FALSE(fuzz::checkCompareTable("no numbers here\n", scratch));  // an error, clearly given
  CHECK_FALSE(fuzz::checkLawTable("time_s,crank_angle_deg\n0,0\n1,90\n2,180\n3,270\n"));
  CHECK_FALSE(fuzz::checkLawTable("time_s,crank_angle_deg\n0,nan\n"));  // the nan is the table's own
  fs::remove(scratch);
}
