// analyze on linkages driven other than by a crank: seed 004's arm through analyze equals the
// arm command (its closed-form inverse kinematics) in every column arm prints, for both
// elbows; a piston and a cylinder take their laws in the length unit.

#include "tests/cli/run_cli.h"

#include "kinematics/design/design.h"
#include "kinematics/io/document_json.h"

#include "tests/support/approx.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using linkwright::test::runCliCommand;
using linkwright::test::within;
namespace k = linkwright::kinematics;

namespace {

// A CSV's columns by name.
std::map<std::string, std::vector<double>> columnsOf(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::istringstream header(line.substr(0, line.find('\r')));
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::istringstream cells(line.substr(0, line.find('\r')));
    std::string cell;
    for (std::size_t c = 0; c < names.size() && std::getline(cells, cell, ','); ++c)
      columns[names[c]].push_back(cell.empty() ? NAN : std::stod(cell));
  }
  return columns;
}

// Every column of `arm` equals analyze's column of the same name to 1e-12.
void checkSameColumns(const std::string& armCsv, const std::string& analyzeCsv) {
  const auto arm = columnsOf(armCsv);
  const auto analyzed = columnsOf(analyzeCsv);
  REQUIRE(arm.size() == 11);
  for (const auto& [name, values] : arm) {
    CAPTURE(name);
    REQUIRE(analyzed.count(name) == 1);
    const std::vector<double>& other = analyzed.at(name);
    REQUIRE(other.size() == values.size());
    for (std::size_t j = 0; j < values.size(); ++j) {
      CAPTURE(j);
      CHECK(other[j] == within(values[j], 1e-12));
    }
  }
}

}  // namespace

TEST_CASE("analyze --example seed-arm equals arm --example seed-arm, elbow down", "[cli][arm][driven]") {
  const auto arm = runCliCommand({"arm", "--example", "seed-arm"});
  const auto analyzed = runCliCommand({"analyze", "--example", "seed-arm"});
  REQUIRE(arm.code == 0);
  REQUIRE(analyzed.code == 0);
  checkSameColumns(arm.out, analyzed.out);
  const auto columns = columnsOf(analyzed.out);
  CHECK(columns.at("upper_angle_deg").front() == within(-38.9424, 5e-5));
  CHECK(columns.at("forearm_omega_rad_s").front() == within(10.54738, 5e-6));
}

TEST_CASE("analyze of the arm document with the elbow up equals arm --elbow up", "[cli][arm][driven]") {
  k::Design d = *k::designForExample("seed-arm");
  std::get<k::RrrPoint>(d.mechanism.points[2].definition).branch = k::Branch::Open;
  const std::string path = (std::filesystem::temp_directory_path() / "linkwright_arm_up.linkwright").string();
  {
    std::ofstream f(path, std::ios::binary);
    f << k::io::writeDocument(d);
  }
  const auto arm = runCliCommand({"arm", "--example", "seed-arm", "--elbow", "up"});
  const auto analyzed = runCliCommand({"analyze", path});
  std::filesystem::remove(path);
  REQUIRE(arm.code == 0);
  REQUIRE(analyzed.code == 0);
  checkSameColumns(arm.out, analyzed.out);
}

TEST_CASE("a piston's law is in millimetres and a cylinder's in metres", "[cli][driven]") {
  // 60 mm of piston travel from 10 mm in 0.1 s on a 3-4-5 rise.
  const auto piston = runCliCommand({"analyze", "--example", "piston-driven", "--law", "345", "--rise", "60",
                                     "--duration", "0.1", "--from", "10", "--samples", "5"});
  REQUIRE(piston.code == 0);
  const auto columns = columnsOf(piston.out);
  CHECK(piston.out.rfind("time_s,C_s_mm,crank_angle_deg,", 0) == 0);
  CHECK(columns.at("C_s_mm").front() == within(10.0, 1e-12));
  CHECK(columns.at("C_s_mm").back() == within(70.0, 1e-12));
  CHECK(columns.at("C_vx_mm_s")[2] == within(1.875 * 60.0 / 0.1, 1e-9));  // the 3-4-5 peak, 15h/8T
  const auto boom = runCliCommand({"extremes", "--example", "excavator-boom"});
  REQUIRE(boom.code == 0);
  CHECK_THAT(boom.out, Catch::StartsWith("extremes over times 0 s to 4 s, refined between 201 samples; the driver "
                                         "follows its motion law"));
  CHECK_THAT(boom.out, Catch::Contains("boom_angle_deg"));
}

TEST_CASE("a linear driver's grid options are refused while its law applies", "[cli][driven][errors]") {
  const auto r = runCliCommand({"analyze", "--example", "excavator-boom", "--to", "1.5"});
  CHECK(r.code != 0);
  CHECK_THAT(r.err, Catch::Contains("--to does not apply: this linkage's driver follows a motion law in time"));
}

TEST_CASE("a cylinder follows a measured s(t) table in metres", "[cli][driven][law]") {
  const std::string path = (std::filesystem::temp_directory_path() / "linkwright_cylinder_table.csv").string();
  {
    std::ofstream f(path, std::ios::binary);
    f << "time_s,actuator_length_m\n0,1.2\n1,1.3\n2,1.5\n3,1.6\n";
  }
  const auto r = runCliCommand(
      {"analyze", "--example", "excavator-boom", "--law", "table", "--law-table", path, "--samples", "4"});
  std::filesystem::remove(path);
  REQUIRE(r.code == 0);
  const auto columns = columnsOf(r.out);
  CHECK(columns.at("actuator_length_m") == std::vector<double>{1.2, 1.3, 1.5, 1.6});
  CHECK(columns.at("time_s") == std::vector<double>{0.0, 1.0, 2.0, 3.0});
}
