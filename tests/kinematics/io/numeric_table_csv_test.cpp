// Reading another tool's table (kinematics/io/numeric_table_csv.h): the delimiter, the decimal
// comma, header rows of any number, quoted cells, empty cells, the printed precision, and the
// errors for a file without numbers or with text among them.

#include "kinematics/io/numeric_table_csv.h"

#include "tests/support/catch.h"

using namespace linkwright::kinematics;
using io::readNumericTable;

TEST_CASE("a comma-separated table with one header row", "[numeric_table]") {
  const auto table = readNumericTable("crank_angle_deg,rocker_omega_rad_s\n0,-0.748\r\n30,0.2037\n");
  REQUIRE(table);
  CHECK(table->delimiter == ',');
  CHECK_FALSE(table->decimalComma);
  REQUIRE(table->columns() == 2);
  CHECK(table->labels[1] == "rocker_omega_rad_s");
  REQUIRE(table->rows.size() == 2);
  CHECK(table->rows[1].line == 3);
  CHECK(*table->rows[1].cells[1] == 0.2037);
  CHECK(table->rounding[0] == 0.5);             // whole degrees
  CHECK(table->rounding[1] == Approx(0.0005));  // the coarsest cell, -0.748
}

TEST_CASE("European Excel: semicolon with a decimal comma, and quoted header cells", "[numeric_table]") {
  const auto table = readNumericTable("\"Angle, deg\";\"omega; rad/s\"\n0;-0,75\n30;0,20\n");
  REQUIRE(table);
  CHECK(table->delimiter == ';');
  CHECK(table->decimalComma);
  CHECK(table->labels[0] == "Angle, deg");
  CHECK(table->labels[1] == "omega; rad/s");
  CHECK(*table->rows[0].cells[1] == -0.75);
  CHECK(table->rounding[1] == Approx(0.005));
}

TEST_CASE("tab-separated with several header rows, comments and empty cells", "[numeric_table]") {
  const auto table =
      readNumericTable("# from a motion study\n\t\tL3-1\nFrame\tTime\tdeg\n1\t0,0\t33,28\n\n2\t0,5\t\n# end\n");
  REQUIRE(table);
  CHECK(table->delimiter == '\t');
  REQUIRE(table->columns() == 3);
  CHECK(table->labels[0] == "Frame");
  CHECK(table->labels[2] == "L3-1 deg");  // the header rows' cells joined; the comment is not one
  REQUIRE(table->rows.size() == 2);
  CHECK(*table->rows[0].cells[2] == 33.28);
  CHECK_FALSE(table->rows[1].cells[2].has_value());
  CHECK(table->rows[1].line == 6);
}

TEST_CASE("exponents keep their printed precision", "[numeric_table]") {
  const auto table = readNumericTable("t,x\n1.5e-3,+2\n");
  REQUIRE(table);
  CHECK(table->rounding[0] == Approx(5e-5));
  CHECK(*table->rows[0].cells[1] == 2.0);
}

TEST_CASE("a file without numbers, or with text after them, is refused naming the line", "[numeric_table]") {
  const auto none = readNumericTable("a,b\nc,d\n");
  REQUIRE_FALSE(none);
  CHECK(none.error().field == "csv");
  CHECK_THAT(none.error().message, Catch::Contains("no numeric row"));
  CHECK_FALSE(readNumericTable(""));
  const auto text = readNumericTable("x,y\n1,2\n3,abc\n");
  REQUIRE_FALSE(text);
  CHECK_THAT(text.error().message, Catch::Contains("line 3") && Catch::Contains("3,abc"));
  CHECK_FALSE(readNumericTable("x,y\n1,nan\n"));  // not a number a table can hold
}

TEST_CASE("a byte-order mark is not part of the first row, and 0e400 is not a measurement", "[numeric_table]") {
  // Excel's UTF-8 BOM before a headerless table: its first row was read as the header.
  const auto bom = readNumericTable(
      "\xEF\xBB\xBF"
      "0,1.5\n30,2.5\n60,3.5\n");
  REQUIRE(bom);
  CHECK(bom->rows.size() == 3);
  CHECK(bom->rows[0].line == 1);
  CHECK(*bom->rows[0].cells[1] == 1.5);
  // A zero written to half of 1e400 claimed a rounding of infinity: its column's tolerance
  // read "undefined" and nothing in it was ever flagged.
  const auto huge = readNumericTable("x,y\n0,0e400\n1,0e400\n");
  REQUIRE_FALSE(huge);
  CHECK_THAT(huge.error().message,
             Catch::Contains("line 2 is not a row of numbers") || Catch::Contains("no numeric row"));
  const auto exponent = readNumericTable("x,y\n0,1.5e2\n1,2e-3\n");
  REQUIRE(exponent);
  CHECK(exponent->rounding[1] == Approx(5.0));  // 1.5e2: to the 10s, the coarsest
}
