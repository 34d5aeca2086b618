// linkwright-cli balance: the balanced design is written as a document whose shaking force
// analyze --forces finds gone, the figures before and after are printed, and every refusal
// (no masses, a linkage it cannot balance, options out of range, a file it cannot write) exits
// with its code and writes nothing.

#include "tests/cli/csv_column.h"
#include "tests/cli/run_cli.h"

#include "tests/support/catch.h"
#include "tests/support/scratch_dir.h"

#include <algorithm>
#include <filesystem>

namespace {

using linkwright::test::runCliCommand;
using linkwright::test::scratchDir;
namespace fs = std::filesystem;

// The largest shaking force in analyze --forces' shaking_N column.
double peakShaking(const std::vector<std::string>& source) {
  std::vector<std::string> args{"analyze"};
  args.insert(args.end(), source.begin(), source.end());
  args.insert(args.end(), {"--forces", "--step", "1"});
  const auto r = runCliCommand(args);
  REQUIRE(r.code == 0);
  const std::vector<double> shaking = linkwright::test::csvColumn(r.out, "shaking_N");
  return *std::max_element(shaking.begin(), shaking.end());
}

}  // namespace

TEST_CASE("balance writes a design whose shaking force analyze --forces finds gone", "[cli][balance]") {
  const fs::path dir = scratchDir("balance-cli");
  const std::string out = (dir / "balanced.linkwright").string();
  const auto r = runCliCommand({"balance", "--example", "funsho-fourbar", "-o", out});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("four-bar: complete shaking-force balance (Berkof and Lowen)") != std::string::npos);
  CHECK(r.out.find("counterweight on crank: 0.4 kg at -10 mm along and 0 mm across the link") != std::string::npos);
  CHECK(r.out.find("counterweight on rocker: 0.5 kg at -20 mm along and 0 mm across the link") != std::string::npos);
  CHECK(r.out.find("bearing load peak") != std::string::npos);
  const double before = peakShaking({"--example", "funsho-fourbar"});
  const double after = peakShaking({out});
  CHECK(before > 100.0);
  CHECK(after <= 1e-9 * before);
  fs::remove_all(dir);
}

TEST_CASE("balance refuses what it cannot balance, and writes nothing", "[cli][balance]") {
  const fs::path dir = scratchDir("balance-cli");
  const std::string out = (dir / "out.linkwright").string();
  const std::string data = LINKWRIGHT_TEST_DATA;
  const std::vector<std::tuple<std::vector<std::string>, int, std::string>> cases{
      {{"balance", "--example", "funsho-fourbar"}, 2, "balance needs -o FILE.linkwright"},
      {{"balance", "-o", out}, 2, "balance needs FILE.json or --example NAME"},
      {{"balance", "--example", "thesis-crank-rocker", "-o", out}, 2, "there are no masses to balance"},
      {{"balance", data + "/watt-ii-masses.linkwright", "-o", out},
       2,
       "shaking-force balance by counterweights is for a four-bar or a slider-crank"},
      {{"balance", "--example", "funsho-fourbar", "--fraction", "2", "-o", out},
       2,
       "--fraction: the fraction of the reciprocating mass to balance must be between 0 and 1 (got 2)"},
      {{"balance", "--example", "funsho-fourbar", "--radius", "0", "-o", out}, 2, "--radius: the counterweight's"},
      {{"balance", "--example", "funsho-fourbar", "-o", (dir / "missing" / "out.linkwright").string()}, 1, ""},
  };
  for (const auto& [args, code, message] : cases) {
    CAPTURE(args);
    const auto r = runCliCommand(args);
    CHECK(r.code == code);
    CHECK(r.err.find(message) != std::string::npos);
    CHECK_FALSE(fs::exists(out));
  }
  CHECK(fs::is_empty(dir));
  fs::remove_all(dir);
}

TEST_CASE("balance --spring writes the spring that lowers the RMS torque, and machine finds it there",
          "[cli][balance][springs]") {
  const fs::path dir = scratchDir("balance-cli");
  const std::string out = (dir / "sprung.linkwright").string();
  const auto r = runCliCommand({"balance", "--example", "funsho-fourbar", "--spring", "rocker:C,O2", "-o", out});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("the spring from C on rocker to the frame at O2") != std::string::npos);
  CHECK(r.out.find("driving torque RMS    0.67087 → 0.55503 N·m") != std::string::npos);
  // The written document's own inverse dynamics give the RMS the balance predicted.
  const auto machine = runCliCommand({"machine", out});
  REQUIRE(machine.code == 0);
  CHECK(machine.out.find("  driving torque, RMS                          0.55503") != std::string::npos);
  const std::vector<std::pair<std::string, std::string>> refused{
      {"rocker:C", "--spring needs two ends"},
      {"rocker:C,X", "--spring: loads.springs[0].second.point names no point of this mechanism (got \"X\")"},
      {"rocker:C,O4", "--spring: a spring from C to O4 cannot change the driving torque"},
  };
  for (const auto& [ends, message] : refused) {
    CAPTURE(ends);
    const auto bad = runCliCommand(
        {"balance", "--example", "funsho-fourbar", "--spring", ends, "-o", (dir / "bad.linkwright").string()});
    CHECK(bad.code == 2);
    CHECK(bad.err.find(message) != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "bad.linkwright"));
  }
  fs::remove_all(dir);
}

TEST_CASE("balance --spring-search adds the spring's two ends and a spring at least as good as given ends",
          "[cli][balance][springs]") {
  const fs::path dir = scratchDir("balance-cli");
  const std::string out = (dir / "searched.linkwright").string();
  const auto r = runCliCommand({"balance", "--example", "funsho-fourbar", "--spring-search", "rocker", "-o", out});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.out.find("on rocker: spring_link at ") != std::string::npos);
  CHECK(r.out.find("on the frame: spring_frame at (") != std::string::npos);
  const std::string rms = "driving torque RMS    0.67087 → ";
  const std::size_t at = r.out.find(rms);
  REQUIRE(at != std::string::npos);
  const double after = std::stod(r.out.substr(at + rms.size()));
  CHECK(after < 0.55503);  // the ends given by hand above (C to O2) reach 0.55503 N·m
  CHECK(r.out.find("at the edge of the search") != std::string::npos);  // 10 mm across a 20 mm rocker
  // The written document, read back, holds both points and gives that RMS by its own forces.
  const auto machine = runCliCommand({"machine", out, "--json"});
  REQUIRE(machine.code == 0);
  const double rmsWritten = std::stod(machine.out.substr(machine.out.find("\"rms_torque_Nm\": ") + 17));
  CHECK(rmsWritten == Approx(after).epsilon(1e-4));

  const std::vector<std::pair<std::vector<std::string>, std::string>> refused{
      {{"--spring-search", "boom"},
       "--spring-search: the spring's link must be one of the linkage's (crank, coupler, "
       "rocker); got \"boom\""},
      {{"--spring-search", "rocker", "--spring", "rocker:C,O2"}, "not both"},
      // A counterweight's options, which a spring balance would ignore.
      {{"--spring-search", "crank", "--radius", "3"},
       "linkwright-cli: --radius sets the counterweights' distance from their pivots, and a spring balance "
       "(--spring-search) makes no counterweight: give one or the other\n"},
      {{"--spring", "rocker:C,O2", "--fraction", "0.5"},
       "linkwright-cli: --fraction sets the share of the reciprocating mass, and a spring balance (--spring) makes "
       "no counterweight: give one or the other\n"},
  };
  for (const auto& [options, message] : refused) {
    std::vector<std::string> args{"balance", "--example", "funsho-fourbar", "-o", (dir / "bad.linkwright").string()};
    args.insert(args.end(), options.begin(), options.end());
    const auto bad = runCliCommand(args);
    CHECK(bad.code == 2);
    CHECK(bad.err.find(message) != std::string::npos);
    CHECK_FALSE(fs::exists(dir / "bad.linkwright"));
  }
  fs::remove_all(dir);
}
