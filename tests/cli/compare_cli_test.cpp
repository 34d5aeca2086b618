// Tests `linkwright-cli compare` in-process on the thesis's own tables (seed 000, typed into
// tests/data/compare/; each file's first line says where in the seed it comes from): the
// Excel Table 7's α4 typo is flagged in 8 rows, SolidWorks' Figure 41 agrees after the fitted
// −0.106° offset; bad tables, maps and options exit with 2, name what is wrong, print nothing.

#include "tests/cli/run_cli.h"
#include "tests/support/catch.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

using linkwright::test::CliRun;
using linkwright::test::runCliCommand;
namespace fs = std::filesystem;

namespace {

std::string data(const std::string& name) { return std::string(LINKWRIGHT_TEST_DATA) + "/compare/" + name; }

const std::string kExcelMap =
    "1=crank-angle:deg,2=coupler_angle:deg,3=rocker_angle:deg,4=coupler_omega:rad/s,5=rocker_omega:rad/s,"
    "6=coupler_alpha:rad/s2,7=rocker_alpha:rad/s2";

CliRun compare(const std::string& table, const std::string& map, std::vector<std::string> more = {}) {
  std::vector<std::string> args{"compare", "--example", "thesis-crank-rocker", table, "--map", map};
  args.insert(args.end(), more.begin(), more.end());
  return runCliCommand(args);
}

fs::path scratchFile(const std::string& text) {
  std::random_device random;
  const fs::path file = fs::temp_directory_path() / ("linkwright-compare-" + std::to_string(random()) + ".csv");
  std::ofstream(file) << text;
  return file;
}

}  // namespace

TEST_CASE("compare: the thesis Excel table flags α4 in its 8 typo rows and exits 0", "[cli][compare]") {
  const CliRun r = compare(data("thesis_excel_table7.tsv"), kExcelMap);
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK_THAT(r.out, Catch::Contains("13 rows, tab-separated, decimal comma"));
  CHECK_THAT(r.out, Catch::Contains("column 7, rocker_alpha rad/s2: 8 of 13 rows beyond"));
  // The flagged rows name the file's lines: 330° is line 16 (0.59 printed, -0.6177 exact).
  CHECK_THAT(r.out, Catch::Contains("16    330  330  ") && Catch::Contains("-0.6177"));
  // The table is at the angles it states: the fit keeps zero and says why.
  CHECK_THAT(r.out, Catch::Contains("offset:    0° (fitted") && Catch::Contains("zero kept"));
  const auto json = nlohmann::json::parse(compare(data("thesis_excel_table7.tsv"), kExcelMap, {"--json"}).out);
  CHECK(json["flagged_rows"] == 8);
  CHECK(json["columns"].size() == 6);
  CHECK(json["columns"][5]["flagged"] == 8);
  CHECK(json["columns"][5]["header"] == "Angular acceleration, α_4 , rad/s ²");
  for (int k = 0; k < 5; ++k) CHECK(json["columns"][k]["flagged"] == 0);
}

TEST_CASE("compare: SolidWorks Figure 41 agrees after the fitted offset of -0.106°", "[cli][compare]") {
  const std::string map = "2=time:s,3=coupler_angle:deg,4=rocker_angle:deg:rev";
  const CliRun r = compare(data("thesis_solidworks_fig41_angles.tsv"), map);
  CHECK(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("offset:    -0.10"));
  CHECK_THAT(r.out, Catch::Contains("every row agrees within the tolerance"));
  const auto json = nlohmann::json::parse(compare(data("thesis_solidworks_fig41_angles.tsv"), map, {"--json"}).out);
  CHECK(json["offset"]["mode"] == "auto");
  CHECK(json["offset"]["deg"].get<double>() == Approx(-0.106).margin(0.0015));
  // A zero tolerance flags the printed rounding; --offset none leaves the 0.106° visible.
  const auto none = nlohmann::json::parse(
      compare(data("thesis_solidworks_fig41_angles.tsv"), map, {"--offset", "none", "--json"}).out);
  CHECK(none["offset"]["deg"] == 0.0);
  CHECK(none["columns"][1]["worst"].get<double>() == Approx(0.106).margin(0.001));
  const CliRun tight = compare(data("thesis_solidworks_fig41_angles.tsv"), map, {"--tolerance", "0,0"});
  CHECK(tight.code == 0);
  CHECK_THAT(tight.out, Catch::Contains("rows beyond"));
}

TEST_CASE("compare: a typo does not pull the offset, and the report says the fit left it out", "[cli][compare]") {
  std::ifstream in(data("thesis_excel_table7.tsv"));
  std::stringstream text;
  text << in.rdbuf();
  std::string table = text.str();
  const std::string right = "90\t16,10\t80,72", wrong = "90\t16,10\t83,72";  // θ4 at 90° 3° off
  REQUIRE(table.find(right) != std::string::npos);
  table.replace(table.find(right), right.size(), wrong);
  const fs::path file = scratchFile(table);
  const CliRun r = compare(file.string(), "1=crank-angle:deg,2=coupler_angle:deg,3=rocker_angle:deg");
  CHECK(r.code == 0);
  CHECK_THAT(r.out,
             Catch::Contains("offset:    0° (fitted") && Catch::Contains("left out of the fit: line 8 (column 3)"));
  CHECK_THAT(r.out, Catch::Contains("column 3, rocker_angle deg: 1 of 13 rows beyond"));
  CHECK_THAT(r.out, !Catch::Contains("column 2, coupler_angle deg:"));
  const auto json = nlohmann::json::parse(
      compare(file.string(), "1=crank-angle:deg,2=coupler_angle:deg,3=rocker_angle:deg", {"--json"}).out);
  CHECK(json["flagged_rows"] == 1);
  CHECK(json["offset"]["kept_zero"] == true);
  CHECK(json["columns"][1]["rows"][3]["outside_fit"] == true);
  fs::remove(file);
}

TEST_CASE("compare: a table without numbers, a wrong unit, a column mapped twice, no x: exit 2", "[cli][compare]") {
  const fs::path words = scratchFile("angle;omega\ndeg;rad/s\n");
  struct Case {
    std::string table, map, message;
  } cases[] = {
      {words.string(), "1=crank-angle,2=rocker_omega", "no numeric row"},
      {data("thesis_excel_table7.tsv"), "1=crank-angle:deg,2=coupler_angle:mm",
       "unit 'mm' does not fit coupler_angle (angle; accepted: deg, rad)"},
      {data("thesis_excel_table7.tsv"), "1=crank-angle,2=coupler_angle,2=rocker_angle", "column 2 is mapped twice"},
      {data("thesis_excel_table7.tsv"), "2=coupler_angle", "no x column"},
      {data("thesis_excel_table7.tsv"), "1=crank-angle,9=coupler_angle", "column 9 is beyond the table"},
      {data("no_such_table.csv"), "1=crank-angle,2=coupler_angle", "cannot be opened"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.map);
    const CliRun r = compare(c.table, c.map);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Catch::Contains(c.message));
  }
  fs::remove(words);
}

TEST_CASE("compare: bad options and missing arguments name the option", "[cli][compare]") {
  const std::string table = data("thesis_excel_table7.tsv");
  CHECK_THAT(compare(table, kExcelMap, {"--offset", "7"}).err, Catch::Contains("--offset must be within ±5"));
  CHECK_THAT(compare(table, kExcelMap, {"--offset", "later"}).err, Catch::Contains("auto, none or a crank angle"));
  CHECK_THAT(compare(table, kExcelMap, {"--tolerance", "150"}).err, Catch::Contains("between 0 and 100"));
  CHECK_THAT(runCliCommand({"compare", "--example", "thesis-crank-rocker", "--map", kExcelMap}).err,
             Catch::Contains("compare needs the other tool's table"));
  CHECK_THAT(runCliCommand({"compare", "--example", "thesis-crank-rocker", table}).err,
             Catch::Contains("compare needs --map"));
  CHECK(compare(table, kExcelMap, {"--offset", "-0.5"}).code == 0);
}

TEST_CASE("compare --help prints the --map syntax and the exit codes", "[cli][compare]") {
  const CliRun r = runCliCommand({"compare", "--help"});
  CHECK(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("--map COLUMN=WHAT[:UNIT][:FLAG...]"));
  CHECK_THAT(r.out, Catch::Contains("crank-angle[:deg|rad]"));
  CHECK_THAT(r.out, Catch::Contains("exit code is 0 whenever it"));
}

TEST_CASE("compare: analyze's own table agrees with the exact solution to round-off", "[cli][compare]") {
  // analyze writes round-trip doubles, so only the solver's own round-off is left.
  const CliRun table = runCliCommand({"analyze", "--example", "thesis-crank-rocker", "--step", "7.5"});
  REQUIRE(table.code == 0);
  const fs::path file = scratchFile(table.out);
  const auto json = nlohmann::json::parse(
      compare(file.string(),
              "1=crank-angle,4=coupler_angle_deg,7=rocker_angle_deg,8=rocker_omega_rad_s,9=rocker_alpha_rad_s2",
              {"--json"})
          .out);
  CHECK(json["offset"]["deg"].get<double>() == Approx(0.0).margin(1e-9));
  for (const auto& column : json["columns"]) {
    CAPTURE(column["quantity"]);
    CHECK(column["compared"] == 49);
    CHECK(std::abs(column["worst"].get<double>()) < 1e-9);
  }
  fs::remove(file);
}

TEST_CASE("compare --map auto takes the mapping the headers propose, and says so", "[cli][compare]") {
  const CliRun r = compare(data("thesis_excel_table7.tsv"), "auto");
  CHECK(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("map:       1=crank-angle:deg,2=coupler_angle:deg,3=rocker_angle:deg,"
                                    "4=coupler_omega:rad/s,5=rocker_omega:rad/s,6=coupler_alpha:rad/s2,"
                                    "7=rocker_alpha:rad/s2"));
  CHECK_THAT(r.out, Catch::Contains("column 7, rocker_alpha rad/s2: 8 of 13 rows beyond"));
  // SolidWorks' "L3-1 Angular Displacement1 (deg)" names no symbol: no guess, exit 2.
  const CliRun unclear = compare(data("thesis_solidworks_fig41_angles.tsv"), "auto");
  CHECK(unclear.code == 2);
  CHECK(unclear.out.empty());
  CHECK_THAT(unclear.err, Catch::Contains("--map auto") && Catch::Contains("give --map"));
}

TEST_CASE("compare checks --from, --rpm, --omega and --alpha as analyze does, naming the option typed",
          "[cli][compare][errors]") {
  const std::string map = "2=time:s,3=coupler_angle:deg,4=rocker_angle:deg:rev";
  const auto refused = [&](std::vector<std::string> options, const std::string& option) {
    CAPTURE(options);
    const CliRun r = compare(data("thesis_solidworks_fig41_angles.tsv"), map, std::move(options));
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Catch::StartsWith("linkwright-cli: " + option + " "));
  };
  refused({"--from", "nan"}, "--from");  // every row "agreed", exit 0
  refused({"--from", "1e300"}, "--from");
  refused({"--rpm", "nan"}, "--rpm");  // blamed --omega
  refused({"--omega", "2e6"}, "--omega");
  // α's domain is ±1e12 rad/s², not ±1e6.
  CHECK(compare(data("thesis_solidworks_fig41_angles.tsv"), map, {"--alpha", "2e6"}).code == 0);
  refused({"--alpha", "2e12"}, "--alpha");
}

TEST_CASE("compare: a long table's offset is fitted on a sample of its rows and finds exactly its typo",
          "[cli][compare][long]") {
  // The thesis four-bar's own table at 12 001 crank angles (three times the rows the fit
  // samples), its crank angles stated 1.5° late, one coupler angle 3° off.
  const CliRun exact = runCliCommand({"analyze", "--example", "thesis-crank-rocker", "--samples", "12001"});
  REQUIRE(exact.code == 0);
  std::istringstream lines(exact.out);
  std::string line, table;
  std::getline(lines, line);
  table += "theta2 (deg),theta3 (deg)\n";
  const int typoRow = 7777;  // line 7779 of the file: the header is line 1
  for (int row = 0; std::getline(lines, line); ++row) {
    std::vector<std::string> cells;
    std::stringstream split(line);
    for (std::string cell; std::getline(split, cell, ',');) cells.push_back(cell);
    // crank_angle_deg, then the crank's ω and α, then coupler_angle_deg.
    double coupler = std::stod(cells[3]);
    if (row == typoRow) coupler += 3.0;
    std::ostringstream out;
    out.precision(12);
    out << std::stod(cells[0]) + 1.5 << "," << coupler << "\n";
    table += out.str();
  }
  const fs::path file = scratchFile(table);
  const CliRun json =
      runCliCommand({"compare", "--example", "thesis-crank-rocker", file.string(), "--map", "auto", "--json"});
  REQUIRE(json.code == 0);
  // Written row by row, yet the very document nlohmann::json lays out.
  const auto doc = nlohmann::json::parse(json.out);
  CHECK(doc.dump(2) + "\n" == json.out);
  CHECK(doc["offset"]["deg"].get<double>() == Approx(-1.5).margin(1e-7));
  const auto& rows = doc["columns"][0]["rows"];
  REQUIRE(rows.size() == 12001);
  std::vector<int> flagged, outside;
  for (const auto& row : rows) {
    if (row["flagged"].get<bool>()) flagged.push_back(row["line"].get<int>());
    if (row["outside_fit"].get<bool>()) outside.push_back(row["line"].get<int>());
  }
  CHECK(flagged == std::vector<int>{typoRow + 2});
  CHECK(outside == std::vector<int>{typoRow + 2});
  const CliRun text = runCliCommand({"compare", "--example", "thesis-crank-rocker", file.string(), "--map", "auto"});
  CHECK_THAT(text.out, Catch::Contains("left out of the fit: line 7779 (column 2)"));
  fs::remove(file);
}

TEST_CASE("compare --json writes a header or a path that is not UTF-8 with U+FFFD, not a crash",
          "[cli][compare][json][errors]") {
  // The fuzzer's finding: a header of Latin-1 bytes threw nlohmann's type_error 316 out of main.
  const fs::path dir = fs::temp_directory_path() / "linkwright-compare-utf8";
  fs::create_directories(dir);
  const fs::path table = dir / "\xFF\xFEtable.csv";
  std::ofstream(table) << "theta2 (deg),theta3 \xB0 (deg),theta4 (deg)\n0,33.2031,58.4119\n90,12.6,54.8\n";
  const CliRun r = compare(table.string(), "auto", {"--json"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto json = nlohmann::json::parse(r.out);
  CHECK(json["table"] == (dir / "\xEF\xBF\xBD\xEF\xBF\xBDtable.csv").string());
  CHECK(json["columns"][0]["header"] == "theta3 \xEF\xBF\xBD (deg)");
  fs::remove_all(dir);
}
