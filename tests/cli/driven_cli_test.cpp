// analyze on linkages driven other than by a crank: seed 004's arm through analyze equals the
// closed-form inverse kinematics (analysis/two_link_arm.h) in every column the arm command
// prints, for both elbows, and the arm command (an alias of analyze) prints those columns; a
// piston and a cylinder take their laws in the length unit.

#include "tests/cli/run_cli.h"

#include "kinematics/analysis/two_link_arm.h"
#include "kinematics/design/design.h"
#include "kinematics/design/redrive.h"
#include "kinematics/io/document_json.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

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

// Seed 004's arm solved in closed form at every row's tip, which runs from (0.3, 0) toward
// (0, 0.3) m at 2 m/s: analyze's columns equal it to 1e-12 (angles modulo a turn).
void checkClosedForm(const std::string& analyzeCsv, k::Branch elbow) {
  const auto columns = columnsOf(analyzeCsv);
  const Eigen::Vector2d from(0.3, 0.0);
  const Eigen::Vector2d velocity = Eigen::Vector2d(-0.3, 0.3).normalized() * 2.0;
  const std::vector<double>& time = columns.at("time_s");
  REQUIRE(time.size() == 101);
  for (std::size_t j = 0; j < time.size(); ++j) {
    CAPTURE(j);
    // The tip as printed (17 digits round-trip); the time only has 12 significant digits.
    const Eigen::Vector2d tip(columns.at("tip_x_m")[j], columns.at("tip_y_m")[j]);
    CHECK((tip - (from + velocity * time[j])).norm() < 1e-12);
    const auto exact = k::solveTwoLinkArm({0.3, 0.2}, elbow, tip, velocity);
    REQUIRE(exact.ok());
    const auto degrees = [](double rad) { return rad * 180.0 / M_PI; };
    const auto sameAngle = [](double a, double b) { return std::abs(std::remainder(a - b, 360.0)) <= 1e-12 * 360.0; };
    CHECK(sameAngle(columns.at("upper_angle_deg")[j], degrees(exact->upperAngle)));
    CHECK(sameAngle(columns.at("forearm_angle_deg")[j], degrees(exact->forearmAngle)));
    CHECK(columns.at("upper_omega_rad_s")[j] == within(exact->upperOmega, 1e-12));
    CHECK(columns.at("forearm_omega_rad_s")[j] == within(exact->forearmOmega, 1e-12));
    CHECK(columns.at("upper_alpha_rad_s2")[j] == within(exact->upperAlpha, 1e-12));
    CHECK(columns.at("forearm_alpha_rad_s2")[j] == within(exact->forearmAlpha, 1e-12));
    CHECK(columns.at("elbow_x_m")[j] == within(exact->elbow.x(), 1e-12));
    CHECK(columns.at("elbow_y_m")[j] == within(exact->elbow.y(), 1e-12));
  }
}

}  // namespace

TEST_CASE("analyze --example seed-arm equals arm --example seed-arm, elbow down", "[cli][arm][driven]") {
  const auto arm = runCliCommand({"arm", "--example", "seed-arm"});
  const auto analyzed = runCliCommand({"analyze", "--example", "seed-arm"});
  REQUIRE(arm.code == 0);
  REQUIRE(analyzed.code == 0);
  checkSameColumns(arm.out, analyzed.out);
  checkClosedForm(analyzed.out, k::Branch::Crossed);
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
  checkClosedForm(analyzed.out, k::Branch::Open);
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

TEST_CASE("a law's --samples out of range is quoted as typed, once named", "[cli][driven][errors]") {
  // It was read as unsigned: -5 came back as 18446744073709551611, and "--samples samples".
  for (const std::string count : {"-5", "0", "10000001"}) {
    CAPTURE(count);
    const auto r = runCliCommand({"analyze", "--example", "excavator-boom", "--samples", count});
    CHECK(r.code == 2);
    CHECK(r.err == "linkwright-cli: --samples must be between 1 and 10000000 (got " + count + ")\n");
  }
  CHECK(runCliCommand({"analyze", "--example", "excavator-boom", "--samples", "3"}).code == 0);
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

TEST_CASE("a four-bar driven from its rocker is analysed in the rocker's angle, a toggle names its links",
          "[cli][driven]") {
  // Frame 40, crank 10, coupler 40, rocker 30: with the rocker at 90° C is (40, 30), 50 from
  // O2, so crank and coupler are stretched in line: the toggle of the rocker-driven linkage.
  const k::Design d = *k::fourBarDesign({40, 10, 40, 30});
  const auto rocker = k::driveFrom(d, d.mechanism.findPoint("C").value(), 0.0);
  REQUIRE(rocker.ok());
  const std::string path = (std::filesystem::temp_directory_path() / "linkwright_rocker_driven.linkwright").string();
  {
    std::ofstream f(path, std::ios::binary);
    f << k::io::writeDocument(rocker->design);
  }
  const auto r = runCliCommand({"analyze", path, "--from", "90", "--to", "110", "--samples", "3"});
  std::filesystem::remove(path);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.err, Catch::Contains("toggle position at rocker angle 90°: coupler and crank are collinear, ω and α "
                                    "are undefined (cells left empty)"));
  const auto columns = columnsOf(r.out);
  CHECK(r.out.rfind("rocker_angle_deg,crank_angle_deg,crank_omega_rad_s,", 0) == 0);  // the input first
  CHECK(columns.at("rocker_angle_deg")[0] == within(90.0, 1e-12));
  CHECK(columns.at("B_x_mm")[0] == within(8.0, 1e-12));  // B on O2–C, 10 mm out of 50
  CHECK(columns.at("B_y_mm")[0] == within(6.0, 1e-12));
  CHECK(std::isnan(columns.at("crank_omega_rad_s")[0]));  // left empty at the toggle
  CHECK(columns.at("rocker_omega_rad_s")[1] == within(1.0, 1e-12));
}

TEST_CASE("examples lists a linkage driven along a path or by an actuator in its driver's units",
          "[cli][driven][examples]") {
  const auto r = runCliCommand({"examples"});
  REQUIRE(r.code == 0);
  // The line under each example's description.
  const auto settings = [&r](const std::string& name) {
    const std::size_t at = r.out.find(name + "\n");
    REQUIRE(at != std::string::npos);
    const std::size_t line = r.out.find('\n', r.out.find('\n', at) + 1) + 1;
    return r.out.substr(line, r.out.find('\n', line) - line);
  };
  // They were shown as "--omega 2 rad/s, every 0.00424264°" and "--omega 1560 rad/s, every 0.39°".
  CHECK(settings("seed-arm") ==
        "  two-link arm (m), its tip path position from 0 m to 0.424264 m in 0.212132 s (mean 2 m/s) on its motion "
        "law, at 101 instants");
  CHECK(settings("piston-driven") ==
        "  slider-crank (mm), its C path position from 1 mm to 79 mm in 0.05 s (mean 1560 mm/s) on its motion law, "
        "at 201 instants");
  CHECK(settings("excavator-boom") ==
        "  cylinder rocker (m), its actuator A–C length from 1.2 m to 1.9 m in 4 s (mean 0.175 m/s) on its motion "
        "law, at 201 instants");
  // A crank keeps rad/s and degrees.
  CHECK(settings("ls3-engine") == "  slider-crank (mm), --omega 691.15 rad/s, every 1°");
}
