// analyze streams: a table of many windows (the sweep solved and written a window at a time)
// is byte for byte the table of the whole sweep written at once, as CSV, with forces and as a
// text table; its memory does not grow with the rows (a run in an address space too small for
// the whole table succeeds); and memory that runs out ends with a sentence and exit 1 (the one
// writer then keeps the old file: tests/kinematics/io/safe_file_test.cpp).

#include "app/cli/arguments.h"
#include "app/cli/commands.h"
#include "app/cli/text_table.h"
#include "tests/cli/run_cli.h"

#include "kinematics/analysis/column_extrema.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/model/number_text.h"
#include "kinematics/solve/sweep_columns.h"

#include "tests/support/catch.h"
#include "tests/support/memory_limit.h"

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace linkwright;

namespace {

const std::string kSixBarWithMasses = std::string(LINKWRIGHT_TEST_DATA) + "/watt-ii-masses.linkwright";

// The table the invocation asks for, computed whole: the options resolved as the CLI does,
// one sweep of every sample, one write.
std::string wholeTable(const std::vector<std::string>& args) {
  const auto inv = cli::parseArguments(args);
  REQUIRE(inv);
  const auto resolved = cli::resolveMechanism(*inv);
  REQUIRE(resolved);
  const auto spec = cli::sweepSpecFor(*inv, resolved->defaults);
  REQUIRE(spec);
  const auto swept = kinematics::sweep(resolved->mechanism, *spec);
  REQUIRE(swept);
  std::optional<kinematics::ForceSweep> forces;
  if (inv->forces) {
    auto solved = kinematics::sweepForces(resolved->mechanism, resolved->dynamics, *swept);
    REQUIRE(solved);
    forces = std::move(solved).value();
  }
  std::ostringstream out;
  const kinematics::ForceSweep* f = forces ? &*forces : nullptr;
  if (inv->tableFormat) cli::writeSweepTable(out, resolved->mechanism, *swept, f);
  else if (f) kinematics::io::writeSweepCsv(out, resolved->mechanism, *swept, *f);
  else kinematics::io::writeSweepCsv(out, resolved->mechanism, *swept);
  return out.str();
}

}  // namespace

TEST_CASE("analyze over many windows writes the whole sweep's table byte for byte", "[cli][streaming]") {
  // 10 001 samples: three windows, the last one short.
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"analyze", "--example", "watt-ii", "--from", "0", "--to", "360", "--step", "0.036"},
        std::vector<std::string>{"analyze", "--example", "funsho-fourbar", "--forces", "--samples", "10001"},
        std::vector<std::string>{"analyze", kSixBarWithMasses, "--forces", "--samples", "10001", "--format", "table"},
        std::vector<std::string>{"analyze", "--fourbar", "60,25,30,45", "--samples", "10001"}}) {
    CAPTURE(args);
    const test::CliRun run = test::runCliCommand(args);
    CHECK(run.code == (args[2] == "60,25,30,45" ? 3 : 0));  // the rocking four-bar has gaps
    CHECK(std::count(run.out.begin(), run.out.end(), '\n') > 5000);
    CHECK(run.out == wholeTable(args));
  }
}

TEST_CASE("analyze of many rows runs in an address space far smaller than its table", "[cli][streaming][memory]") {
  if (!test::memoryLimitsWork()) {
    WARN("address-space limits do not apply under AddressSanitizer: not run");
    return;
  }
  // 300 000 rows of a six-bar with forces: about 200 MB of text, and as much again of columns
  // held whole before the table streamed. 48 MB more than the process holds is plenty now.
  const auto run = test::runWithMemoryLimit(48u << 20, [](std::string& err) {
    const test::CliRun r =
        test::runCliCommand({"analyze", kSixBarWithMasses, "--forces", "--samples", "300000", "-o", "/dev/null"});
    err = r.err;
    return r.code;
  });
  CHECK(run.err.empty());
  CHECK(run.code == 0);
}

TEST_CASE("extremes over many windows are the whole sweep's, and need no more memory", "[cli][streaming][memory]") {
  // 10 001 samples in three windows against the whole sweep's columns scanned at once.
  const std::vector<std::string> args{"extremes", "--example", "watt-ii", "--samples", "10001"};
  const test::CliRun run = test::runCliCommand(args);
  REQUIRE(run.code == 0);
  const auto inv = cli::parseArguments(args);
  const auto resolved = cli::resolveMechanism(*inv);
  const auto spec = cli::sweepSpecFor(*inv, resolved->defaults);
  const auto whole = kinematics::sweep(resolved->mechanism, *spec);
  REQUIRE(whole);
  std::size_t rows = 0;
  for (const auto& column : kinematics::sweepColumns(resolved->mechanism, whole->request)) {
    if (column.quantity == kinematics::ColumnQuantity::InputAngle) continue;
    const auto e = kinematics::columnExtrema(resolved->mechanism, *spec, *whole, column);
    REQUIRE(e);
    // The row names the column and both refined values, printed to 9 digits.
    const auto at = run.out.find("\n" + column.name + " ");
    REQUIRE(at != std::string::npos);
    const std::string row = run.out.substr(at + 1, run.out.find('\n', at + 1) - at - 1);
    CHECK(row.find(kinematics::formatShort(e->minimum.value, 9)) != std::string::npos);
    CHECK(row.find(kinematics::formatShort(e->maximum.value, 9)) != std::string::npos);
    ++rows;
  }
  CHECK(rows > 30);
  if (!test::memoryLimitsWork()) return;
  const auto limited = test::runWithMemoryLimit(48u << 20, [](std::string& err) {
    const test::CliRun r = test::runCliCommand({"extremes", kSixBarWithMasses, "--samples", "300000"});
    err = r.err;
    return r.code;
  });
  CHECK(limited.err.empty());
  CHECK(limited.code == 0);
}

TEST_CASE("memory that runs out ends with a sentence and exit 1", "[cli][streaming][memory]") {
  if (!test::memoryLimitsWork()) {
    WARN("address-space limits do not apply under AddressSanitizer: not run");
    return;
  }
  // A compare table of 400 000 rows (about 9 MB) is read and held whole: more than 4 MB of room.
  const auto dir = std::filesystem::temp_directory_path() / "linkwright-out-of-memory";
  std::filesystem::create_directories(dir);
  const std::string table = (dir / "big.csv").string();
  {
    std::ofstream t(table);
    t << "crank_angle_deg,theta3_deg\n";
    for (int i = 0; i < 400000; ++i) t << (i % 360) << ".000001," << 20.0 + (i % 7) << "\n";
  }
  const auto compare = test::runWithMemoryLimit(4u << 20, [&](std::string& err) {
    const test::CliRun r = test::runCliCommand({"compare", table, "--example", "thesis-crank-rocker", "--map", "auto"});
    err = r.err;
    return r.code;
  });
  CAPTURE(compare.err);
  CHECK(compare.code == 1);
  CHECK(compare.err.find("out of memory") != std::string::npos);
  std::filesystem::remove_all(dir);
}
