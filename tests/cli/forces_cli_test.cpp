// linkwright-cli analyze --forces: the force columns follow the kinematic ones with their
// units, their values are the core's, a document's dynamics are used (with a crank, a point
// driven along a path or a cylinder as the driver), and a linkage without masses (or with a
// unit forces cannot convert) is refused with exit code 2.

#include "app/cli/cli.h"
#include "tests/cli/run_cli.h"

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/dynamics/force_columns.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/io/document_json.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using namespace linkwright;

using Run = test::CliRun;
Run run(const std::vector<std::string>& args) { return test::runCliCommand(args); }

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream s(text);
  for (std::string part; std::getline(s, part, separator);) parts.push_back(part);
  return parts;
}

std::vector<std::string> lines(const std::string& csv) {
  std::vector<std::string> out;
  for (std::string line : split(csv, '\n')) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    out.push_back(line);
  }
  return out;
}

std::size_t columnOf(const std::vector<std::string>& header, const std::string& name) {
  const auto it = std::find(header.begin(), header.end(), name);
  REQUIRE(it != header.end());
  return static_cast<std::size_t>(it - header.begin());
}

}  // namespace

TEST_CASE("analyze --forces appends the force columns with their units", "[cli][forces]") {
  const Run r = run({"analyze", "--example", "funsho-fourbar", "--forces", "--step", "30"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto rows = lines(r.out);
  REQUIRE(rows.size() == 14);  // header and 0°, 30°, …, 360°
  const auto header = split(rows[0], ',');
  const std::vector<std::string> forceNames{"F_O2_x_N",
                                            "F_O2_y_N",
                                            "F_O2_N",
                                            "F_O4_x_N",
                                            "F_O4_y_N",
                                            "F_O4_N",
                                            "F_B_x_N",
                                            "F_B_y_N",
                                            "F_B_N",
                                            "F_C_x_N",
                                            "F_C_y_N",
                                            "F_C_N",
                                            "T_drive_Nm",
                                            "T_drive_virtual_work_Nm",
                                            "T_drive_difference_Nm",
                                            "shaking_x_N",
                                            "shaking_y_N",
                                            "shaking_N",
                                            "shaking_moment_Nm"};
  REQUIRE(header.size() > forceNames.size());
  CHECK(std::vector<std::string>(header.end() - static_cast<std::ptrdiff_t>(forceNames.size()), header.end()) ==
        forceNames);
  CHECK(header[0] == "crank_angle_deg");

  // The torque column is the core's, to the last digit (the CSV is round-trip precise).
  using namespace kinematics;
  const auto example = *findExample("funsho-fourbar");
  const Mechanism& m = example.mechanism;
  const auto s = sweep(m, {0.0, degToRad(360.0), 13, example.omega, 0.0}).value();
  const auto f = sweepForces(m, example.dynamics, s).value();
  const std::size_t torque = columnOf(header, "T_drive_Nm");
  const std::size_t byVirtualWork = columnOf(header, "T_drive_virtual_work_Nm");
  const std::size_t difference = columnOf(header, "T_drive_difference_Nm");
  double peak = 0.0;
  for (const double t : f.driveTorque) peak = std::max(peak, std::abs(t));
  for (std::size_t j = 0; j < 13; ++j) {
    CAPTURE(j);
    const auto cells = split(rows[j + 1], ',');
    CHECK(std::stod(cells[torque]) == f.driveTorque[j]);
    // Virtual work beside it, and their difference at round-off.
    CHECK(std::stod(cells[byVirtualWork]) == f.virtualWorkTorque[j]);
    CHECK(std::abs(std::stod(cells[difference])) <= 1e-9 * peak);
  }
}

TEST_CASE("analyze --forces --format table shows the force sizes and the torque", "[cli][forces]") {
  const Run r = run({"analyze", "--example", "funsho-fourbar", "--forces", "--step", "90", "--format", "table"});
  REQUIRE(r.code == 0);
  const auto rows = lines(r.out);
  CHECK_THAT(rows[0], Catch::Contains("F_O2_N") && Catch::Contains("T_drive_Nm") && Catch::Contains("shaking_N"));
  CHECK_THAT(rows[0], !Catch::Contains("F_O2_x_N"));
  CHECK_THAT(rows[1], Catch::Contains("-2.1352"));  // T_drive at 0°, N·m
}

TEST_CASE("analyze --forces without masses is refused with exit code 2", "[cli][forces][errors]") {
  const Run example = run({"analyze", "--example", "thesis-crank-rocker", "--forces"});
  CHECK(example.code == 2);
  CHECK(example.out.empty());
  CHECK_THAT(example.err,
             Catch::Contains("--forces needs masses and loads, and the example thesis-crank-rocker has none"));
  const Run fourBar = run({"analyze", "--fourbar", "60,25,70,45", "--forces"});
  CHECK(fourBar.code == 2);
  CHECK_THAT(fourBar.err, Catch::Contains("--fourbar has none"));
  const Run classify = run({"classify", "--example", "funsho-fourbar", "--forces"});
  CHECK(classify.code == 2);
  CHECK_THAT(classify.err, Catch::Contains("unknown option '--forces' for 'classify'"));
  const Run value = run({"analyze", "--example", "funsho-fourbar", "--forces=yes"});
  CHECK(value.code == 2);
  CHECK_THAT(value.err, Catch::Contains("--forces takes no value"));
}

TEST_CASE("analyze FILE.json --forces uses the document's dynamics and checks its unit", "[cli][forces]") {
  using namespace kinematics;
  auto design = *designForExample("funsho-fourbar");
  const auto path = (std::filesystem::temp_directory_path() / "linkwright_cli_forces.json").string();
  std::ofstream(path, std::ios::binary) << io::writeDocument(design);
  const Run fromFile = run({"analyze", path, "--forces", "--step", "30"});
  const Run fromExample = run({"analyze", "--example", "funsho-fourbar", "--forces", "--step", "30"});
  CHECK(fromFile.code == 0);
  CHECK(fromFile.out == fromExample.out);

  design.mechanism.lengthUnit = "furlong";
  std::ofstream(path, std::ios::binary | std::ios::trunc) << io::writeDocument(design);
  const Run badUnit = run({"analyze", path, "--forces"});
  CHECK(badUnit.code == 2);
  CHECK_THAT(badUnit.err, Catch::Contains("--forces: lengthUnit must be m, cm, mm, in or ft for forces"));
  CHECK(run({"analyze", path}).code == 0);  // the kinematics need no SI unit
  std::filesystem::remove(path);
}

TEST_CASE("analyze FILE --forces: a path-driven arm and a cylinder-driven boom, as the core gives them",
          "[cli][forces][driven]") {
  using namespace kinematics;
  const Eigen::Vector2d g = standardGravity();
  struct Case {
    std::string example;
    LinkageDynamics dynamics;
    std::vector<std::string> forceNames;
  };
  const std::vector<Case> cases{
      {"seed-arm",
       {{{"upper", 2.0, LinkFramePoint{0.15, 0.0}, 0.02}, {"forearm", 1.5, LinkFramePoint{0.1, 0.0}, 0.006}},
        {},
        {g, {}, {{"forearm", "tip", 0, Eigen::Vector2d(0.0, -20.0)}}}},
       {"F_O_x_N", "F_O_y_N", "F_O_N", "F_elbow_x_N", "F_elbow_y_N", "F_elbow_N", "tip_drive_fx_N", "tip_drive_fy_N",
        "tip_drive_force_N", "O_joint_torque_Nm", "elbow_joint_torque_Nm", "shaking_x_N", "shaking_y_N", "shaking_N",
        "shaking_moment_Nm"}},
      {"excavator-boom",
       {{{"boom", 50.0, LinkFramePoint{1.4, 0.05}, 30.0}},
        {},
        {g, {}, {{"boom", "tip", 0, Eigen::Vector2d(0.0, -2000.0)}}}},
       {"F_O_x_N", "F_O_y_N", "F_O_N", "actuator_force_N", "shaking_x_N", "shaking_y_N", "shaking_N",
        "shaking_moment_Nm"}}};
  for (const Case& c : cases) {
    CAPTURE(c.example);
    Design design = *designForExample(c.example);
    design.dynamics = c.dynamics;
    const auto path =
        (std::filesystem::temp_directory_path() / ("linkwright_cli_forces_" + c.example + ".json")).string();
    std::ofstream(path, std::ios::binary) << io::writeDocument(design);
    const Run r = run({"analyze", path, "--forces"});
    std::filesystem::remove(path);
    INFO(r.err);
    REQUIRE(r.code == 0);
    const auto rows = lines(r.out);
    const auto header = split(rows[0], ',');
    REQUIRE(header.size() > c.forceNames.size());
    CHECK(std::vector<std::string>(header.end() - static_cast<std::ptrdiff_t>(c.forceNames.size()), header.end()) ==
          c.forceNames);
    CHECK(header[0] == "time_s");

    // One row mid-move, every force cell the core's to the last digit.
    const auto s = sweep(design.mechanism, designSweepSpec(design)).value();
    const auto f = sweepForces(design.mechanism, design.dynamics, s).value();
    const std::size_t j = s.size() / 3;
    REQUIRE(f.ok(j));
    const auto row = split(rows[j + 1], ',');
    REQUIRE(row.size() == header.size());
    for (const kinematics::ForceColumn& column : kinematics::forceColumns(f.bodies)) {
      CAPTURE(column.name);
      CHECK(std::stod(row[columnOf(header, column.name)]) == column.value(f, j));
    }
  }
}

TEST_CASE("help: --help lists --forces, its columns and its exit code", "[cli][forces]") {
  const Run r = run({"--help", "analyze"});
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("--forces") && Catch::Contains("T_drive_Nm") && Catch::Contains("F_<joint>_x_N") &&
                        Catch::Contains("actuator_force_N") && Catch::Contains("<point>_drive_force_N") &&
                        Catch::Contains("_joint_torque_Nm") &&
                        Catch::Contains("--forces for a linkage without masses"));
}
