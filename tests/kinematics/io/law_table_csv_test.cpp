// io/law_table_csv.h: a measured q(t) read from CSV text, in the driver's own unit: a crank's
// angle in degrees or radians, a linear driver's position in the linkage's length unit; an s(t)
// table of a polynomial reproduces it; bad files are refused naming the line.

#include "kinematics/io/law_table_csv.h"
#include "kinematics/model/units.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

using namespace linkwright::kinematics;
using linkwright::test::within;

TEST_CASE("a table names its unit: degrees or radians for a crank, the length unit otherwise", "[io][law]") {
  const std::string degrees = "time_s,crank_angle_deg\r\n0,0\r\n1,90\r\n2,180\r\n3,270\r\n";
  const auto crank = io::readLawTableCsv(degrees, InputKind::Angle, "mm");
  REQUIRE(crank);
  CHECK(crank->position[1] == degToRad(90.0));
  const auto radians = io::readLawTableCsv("time_s,q_rad\n0,0\n1,1\n2,2\n3,3\n", InputKind::Angle, "mm");
  REQUIRE(radians);
  CHECK(radians->position[3] == 3.0);
  // s(t) = 0.01 t³ − 0.02 t² + 0.3 t (m), a cubic: the spline reproduces it between its rows.
  std::string cubic = "time_s,tip_s_m\n";
  const auto s = [](double t) { return 0.01 * t * t * t - 0.02 * t * t + 0.3 * t; };
  for (int i = 0; i <= 8; ++i) cubic += std::to_string(0.25 * i) + "," + std::to_string(s(0.25 * i)) + "\n";
  const auto tip = io::readLawTableCsv(cubic, InputKind::Length, "m");
  REQUIRE(tip);
  for (const double t : {0.1, 0.8, 1.37, 1.99})
    CHECK(motionAt(MotionLaw{*tip}, t).position == within(s(t), 1e-6));  // to_string's 6 decimals
}

TEST_CASE("a table without its unit, or with a bad row, is refused naming the line", "[io][law][errors]") {
  const auto degreesForLength = io::readLawTableCsv("time_s,tip_deg\n0,0\n1,1\n2,2\n3,3\n", InputKind::Length, "mm");
  REQUIRE_FALSE(degreesForLength);
  CHECK(degreesForLength.error().message ==
        "the first line must name the columns time_s and the position in the linkage's unit, e.g. "
        "time_s,position_mm (got 'time_s,tip_deg')");
  const auto noUnit = io::readLawTableCsv("time,angle\n0,0\n", InputKind::Angle, "mm");
  REQUIRE_FALSE(noUnit);
  CHECK_THAT(noUnit.error().message, Catch::Contains("e.g. time_s,crank_angle_deg (got 'time,angle')"));
  const auto badRow = io::readLawTableCsv("time_s,s_mm\n0,0\n1,x\n", InputKind::Length, "mm");
  REQUIRE_FALSE(badRow);
  CHECK(badRow.error().message == "line 3: expected two numbers (got '1,x')");
  const auto short_ = io::readLawTableCsv("time_s,s_mm\n0,0\n1,1\n", InputKind::Length, "mm");
  REQUIRE_FALSE(short_);
  CHECK_THAT(short_.error().message, Catch::Contains("at least four rows"));
}

TEST_CASE("a law table after a UTF-8 byte-order mark reads as without it", "[io][law]") {
  const std::string table = "time_s,q_deg\n0,0\n1,10\n2,20\n3,30\n";
  const auto plain = io::readLawTableCsv(table, InputKind::Angle, "mm");
  const auto marked = io::readLawTableCsv("\xEF\xBB\xBF" + table, InputKind::Angle, "mm");
  REQUIRE(plain);
  REQUIRE(marked);
  CHECK(*marked == *plain);
}
