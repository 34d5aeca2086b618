// The column mapping (kinematics/compare/column_mapping.h): the --map text read and written
// back, the quantities and units of the thesis crank-rocker, and each refusal naming the entry
// or column, the value and what is accepted.

#include "kinematics/compare/column_mapping.h"
#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

using namespace linkwright::kinematics;
using namespace linkwright::kinematics::compare;

namespace {

Mechanism thesis() { return designForExample("thesis-crank-rocker")->mechanism; }

io::NumericTable threeColumns() { return *io::readNumericTable("t,a,b\n0,1,2\n0.5,3,4\n"); }

}  // namespace

TEST_CASE("the quantities are analyze's columns without their units", "[compare][mapping]") {
  const auto quantities = compareQuantities(thesis());
  std::vector<std::string> keys;
  for (const CompareQuantity& q : quantities) keys.push_back(q.key);
  CHECK(keys.front() == "crank_angle");
  for (const char* key :
       {"coupler_angle", "rocker_angle", "rocker_omega", "rocker_alpha", "transmission_angle", "C_x", "C_vy", "B_ax"})
    CHECK(std::find(keys.begin(), keys.end(), key) != keys.end());
}

TEST_CASE("A --map text is read, with units, flags and implied units, and written back", "[compare][mapping]") {
  const auto mapping = parseColumnMap(
      "2=time:s, 3=coupler_angle:deg,4=rocker_angle:rad:rev;5=rocker_omega:deg/s:abs,6=rocker_alpha_rad_s2:neg",
      thesis());
  REQUIRE(mapping);
  REQUIRE(mapping->axis);
  CHECK(mapping->axis->column == 1);
  CHECK(mapping->axis->kind == AxisKind::Time);
  REQUIRE(mapping->columns.size() == 4);
  CHECK(mapping->columns[1].reversed);
  CHECK(mapping->columns[1].unit.factor == Approx(180.0 / kPi));
  CHECK(mapping->columns[2].magnitude);
  CHECK(mapping->columns[2].unit.factor == Approx(kPi / 180.0));
  CHECK(mapping->columns[3].unit.name == "rad/s2");  // from the full column name
  CHECK(mapping->columns[3].negated);
  const std::string text = formatColumnMap(*mapping);
  CHECK(text ==
        "2=time:s,3=coupler_angle:deg,4=rocker_angle:rad:rev,5=rocker_omega:deg/s:abs,6=rocker_alpha:rad/s2:neg");
  const auto again = parseColumnMap(text, thesis());
  REQUIRE(again);
  CHECK(formatColumnMap(*again) == text);
  CHECK(parseColumnMap("1=crank-angle:rad,2=C_vx:m/s", thesis())->columns[0].unit.factor == Approx(1000.0));
  CHECK(parseColumnMap("1=crank-angle,2=rocker_alpha:deg/sec**2", thesis())->columns[0].unit.name == "deg/s2");
}

TEST_CASE("a unit that does not fit the quantity names the entry, the unit and the accepted ones",
          "[compare][mapping]") {
  const auto wrong = parseColumnMap("1=crank-angle:deg,2=coupler_angle:mm", thesis());
  REQUIRE_FALSE(wrong);
  CHECK(wrong.error().field == "--map");
  CHECK_THAT(wrong.error().message,
             Catch::Contains("2=coupler_angle:mm") && Catch::Contains("'mm'") && Catch::Contains("accepted: deg, rad"));
  const auto axis = parseColumnMap("1=crank-angle:s", thesis());
  REQUIRE_FALSE(axis);
  CHECK_THAT(axis.error().message, Catch::Contains("accepted: deg, rad"));
  const auto unknown = parseColumnMap("1=crank-angle,2=theta3", thesis());
  REQUIRE_FALSE(unknown);
  CHECK_THAT(unknown.error().message, Catch::Contains("'theta3'") && Catch::Contains("coupler_angle"));
  const auto flag = parseColumnMap("1=crank-angle,2=rocker_omega:rad/s:abs:cw", thesis());
  REQUIRE_FALSE(flag);
  CHECK_THAT(flag.error().message, Catch::Contains("'cw'"));
  CHECK_FALSE(parseColumnMap("x=time", thesis()));
  CHECK_FALSE(parseColumnMap("0=time", thesis()));
  CHECK_FALSE(parseColumnMap("1=time,2=crank-angle", thesis()));  // two x columns
}

TEST_CASE("a mapping that does not fit its table is refused naming the column", "[compare][mapping]") {
  const Mechanism m = thesis();
  const io::NumericTable table = threeColumns();
  const auto check = [&](const std::string& text) { return checkColumnMapping(*parseColumnMap(text, m), table); };
  CHECK_FALSE(check("1=time,2=coupler_angle,3=rocker_angle").has_value());
  const auto twice = check("1=time,2=coupler_angle,2=rocker_angle");
  REQUIRE(twice);
  CHECK(twice->message == "column 2 is mapped twice; map each column once");
  const auto noX = check("2=coupler_angle");
  REQUIRE(noX);
  CHECK_THAT(noX->message, Catch::StartsWith("no x column"));
  const auto beyond = check("1=time,4=coupler_angle");
  REQUIRE(beyond);
  CHECK_THAT(beyond->message, Catch::Contains("column 4") && Catch::Contains("3 columns"));
  const auto rev = check("1=time,2=rocker_omega:rad/s:rev");
  REQUIRE(rev);
  CHECK_THAT(rev->message, Catch::Contains("column 2") && Catch::Contains("angles"));
  const auto nothing = check("1=time");
  REQUIRE(nothing);
  CHECK_THAT(nothing->message, Catch::Contains("no quantity mapped"));
  const io::NumericTable gaps = *io::readNumericTable("t,a\n0,1\n,2\n");
  const auto emptyX = checkColumnMapping(*parseColumnMap("1=time,2=coupler_angle", m), gaps);
  REQUIRE(emptyX);
  CHECK_THAT(emptyX->message, Catch::Contains("empty on line 3"));
}

TEST_CASE("a value no linkage reaches is refused naming the column, line, value and bound", "[compare][mapping]") {
  const Mechanism m = thesis();
  const auto check = [&](const std::string& csv, const std::string& map) {
    return checkColumnMapping(*parseColumnMap(map, m), *io::readNumericTable(csv));
  };
  // 1e308 degrees would even "agree" with any angle modulo a turn.
  const auto angle = check("x,a\n0,10\n30,1e308\n", "1=crank-angle,2=rocker_angle:deg");
  REQUIRE(angle);
  CHECK(angle->field == "map");
  CHECK_THAT(angle->message, Catch::Contains("column 2") && Catch::Contains("1e+308 deg") &&
                                 Catch::Contains("line 3") && Catch::Contains("±1e+06 deg"));
  // The bound follows the column's unit: 1e6° is 17453 rad.
  CHECK(check("x,a\n0,17000\n", "1=crank-angle,2=rocker_angle:rad") == std::nullopt);
  const auto radians = check("x,a\n0,18000\n", "1=crank-angle,2=rocker_angle:rad");
  REQUIRE(radians);
  CHECK_THAT(radians->message, Catch::Contains("±1.75e+04 rad"));
  // The x column too, and every dimension: a rate, a length.
  const auto x = check("x,a\n-1e7,10\n", "1=crank-angle,2=rocker_angle");
  REQUIRE(x);
  CHECK_THAT(x->message, Catch::Contains("column 1") && Catch::Contains("angle"));
  const auto time = check("t,a\n2e9,10\n", "1=time,2=rocker_angle");
  REQUIRE(time);
  CHECK_THAT(time->message, Catch::Contains("time"));
  const auto rate = check("x,w\n0,1e13\n", "1=crank-angle,2=rocker_omega:rad/s");
  REQUIRE(rate);
  CHECK_THAT(rate->message, Catch::Contains("angular velocity"));
  // Large but possible: a rocker ω of 1e5 rad/s near a toggle, an angle unwrapped over 1000 turns.
  CHECK(check("x,w,a\n0,1e5,360000\n", "1=crank-angle,2=rocker_omega:rad/s,3=coupler_angle") == std::nullopt);
}
