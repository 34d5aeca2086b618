// Force columns (force_columns.h) and the CSV they make: names with units for pins, slider
// blocks and the frame, values from the force sweep, empty cells where forces are undefined.

#include "kinematics/dynamics/force_columns.h"
#include "kinematics/design/examples.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <cmath>
#include <sstream>

using namespace linkwright::kinematics;

namespace {

std::vector<std::string> names(const std::vector<ForceColumn>& columns) {
  std::vector<std::string> out;
  for (const auto& c : columns) out.push_back(c.name);
  return out;
}

}  // namespace

TEST_CASE("force columns of a shaper: pins, the slotted link's block, the ram and the frame", "[io][dynamics]") {
  const auto model = bodiesOf(makeShaper(kSeedShaper).value()).value();
  CHECK(names(forceColumns(model)) == std::vector<std::string>{"F_O2_x_N",
                                                               "F_O2_y_N",
                                                               "F_O2_N",
                                                               "F_O4_x_N",
                                                               "F_O4_y_N",
                                                               "F_O4_N",
                                                               "F_B_x_N",
                                                               "F_B_y_N",
                                                               "F_B_N",
                                                               "F_D_x_N",
                                                               "F_D_y_N",
                                                               "F_D_N",
                                                               "F_R_x_N",
                                                               "F_R_y_N",
                                                               "F_R_N",
                                                               "N_B_D_N",
                                                               "M_B_D_Nm",
                                                               "N_R_N",
                                                               "M_R_Nm",
                                                               "T_drive_Nm",
                                                               "T_drive_virtual_work_Nm",
                                                               "T_drive_difference_Nm",
                                                               "shaking_x_N",
                                                               "shaking_y_N",
                                                               "shaking_N",
                                                               "shaking_moment_Nm"});
}

TEST_CASE("the CSV with forces leaves force cells empty where they are undefined", "[io][dynamics]") {
  // A toggle at 0° (B and O4 20 apart = coupler − rocker): rates and forces undefined there.
  const Mechanism m = makeFourBar({30.0, 10.0, 35.0, 15.0}, Branch::Open).value();
  LinkageDynamics d;
  d.links = {{"rocker", 0.5, std::nullopt, std::nullopt}};
  const auto s = sweep(m, {0.0, degToRad(90.0), 4, 10.0, 0.0}).value();
  const auto f = sweepForces(m, d, s).value();
  std::ostringstream out;
  io::writeSweepCsv(out, m, s, f);
  std::vector<std::string> rows;
  std::stringstream text(out.str());
  for (std::string line; std::getline(text, line);) rows.push_back(line);
  REQUIRE(rows.size() == 5);
  CHECK_THAT(rows[0], Catch::EndsWith(",T_drive_Nm,T_drive_virtual_work_Nm,T_drive_difference_Nm,shaking_x_N,"
                                      "shaking_y_N,shaking_N,shaking_moment_Nm\r"));
  CHECK_THAT(rows[1], Catch::EndsWith(",,,,,,,,,,,,,,,,,,,\r"));  // 19 empty force cells at the toggle
  const std::string torque = formatDouble(f.driveTorque[1]);
  CHECK_THAT(rows[2], Catch::Contains("," + torque + ","));
  const auto columns = forceColumns(f.bodies);
  CHECK(columns[2].value(f, 2) == f.revolute[0][2].norm());
  CHECK(columns[12].name == "T_drive_Nm");
  CHECK(columns[12].value(f, 3) == f.driveTorque[3]);
  CHECK(columns[13].value(f, 3) == f.virtualWorkTorque[3]);
  CHECK(columns[14].value(f, 3) == f.driveTorque[3] - f.virtualWorkTorque[3]);
  CHECK(std::abs(columns[14].value(f, 3)) <= 1e-9 * std::abs(f.driveTorque[3]));
  CHECK(f.driveTorque[3] != 0.0);
}
