// The mapping a table's headers propose (kinematics/compare/header_mapping.h): the thesis's own
// Excel headers, textbook symbols in ASCII and Greek with their units, analyze's column names,
// and the headers that must propose nothing (two symbols, a unit that does not fit, unknown).

#include "kinematics/compare/header_mapping.h"
#include "kinematics/design/design.h"

#include "tests/support/catch.h"

#include <fstream>
#include <sstream>

using namespace linkwright::kinematics;
using namespace linkwright::kinematics::compare;

namespace {

Mechanism thesis() { return designForExample("thesis-crank-rocker")->mechanism; }

std::string proposed(const std::string& csv, const Mechanism& m = thesis()) {
  const auto table = io::readNumericTable(csv);
  REQUIRE(table);
  return formatColumnMap(proposeColumnMapping(*table, m));
}

}  // namespace

TEST_CASE("the thesis's Excel headers propose its whole mapping", "[compare][mapping]") {
  std::ifstream file(std::string(LINKWRIGHT_TEST_DATA) + "/compare/thesis_excel_table7.tsv");
  std::stringstream text;
  text << file.rdbuf();
  // "Angle, θ_2 , deg v_2 , ueg", "Angular velocity, ω_3 , rad/s", "… α_4 , rad/s ²": the map
  // the docs write by hand for this table.
  CHECK(proposed(text.str()) ==
        "1=crank-angle:deg,2=coupler_angle:deg,3=rocker_angle:deg,4=coupler_omega:rad/s,5=rocker_omega:rad/s,"
        "6=coupler_alpha:rad/s2,7=rocker_alpha:rad/s2");
}

TEST_CASE("textbook symbols in ASCII or Greek propose the quantity and the header's unit", "[compare][mapping]") {
  CHECK(proposed("Theta2 (deg),Theta4 (deg),omega4 [rad/s],Alpha3 (deg/s^2)\n0,1,2,3\n") ==
        "1=crank-angle:deg,2=rocker_angle:deg,3=rocker_omega:rad/s,4=coupler_alpha:deg/s2");
  CHECK(proposed("θ2 [rad];θ3 [°];ω3 [rpm]\n0;1;2\n") == "1=crank-angle:rad,2=coupler_angle:deg,3=coupler_omega:rpm");
  // Without a unit, the quantity's first (the sweep's own).
  CHECK(proposed("t,theta_3,omega_4\n0,1,2\n") == "1=time:s,2=coupler_angle:deg,3=rocker_omega:rad/s");
  CHECK(proposed("Time (ms),alpha4\n0,1\n") == "1=time:ms,2=rocker_alpha:rad/s2");
  // A crank angle is the x before a time column.
  CHECK(proposed("time (s),crank angle (rad),theta4\n0,1,2\n") == "2=crank-angle:rad,3=rocker_angle:deg");
}

TEST_CASE("analyze's own column names map themselves", "[compare][mapping]") {
  CHECK(proposed("crank_angle_deg,rocker_omega_rad_s,C_x_mm\n0,1,2\n") ==
        "1=crank-angle:deg,2=rocker_omega:rad/s,3=C_x:mm");
  CHECK(proposed("time_s,coupler_angle_deg\n0,1\n") == "1=time:s,2=coupler_angle:deg");
}

TEST_CASE("unclear headers propose nothing", "[compare][mapping]") {
  // Two symbols, a unit that does not fit, a link the numbering has not got, a plain word.
  CHECK(proposed("theta3 - theta4,theta4 (mm),omega7,velocity,L4-1 Angular Displacement2 (deg)\n0,1,2,3,4\n").empty());
  // A four-bar's rocker symbols mean nothing for a two-link arm.
  CHECK(proposed("theta2,theta4\n0,1\n", designForExample("seed-arm")->mechanism) == "1=crank-angle:deg");
}
