// ui/number_text.h: the GUI's read-outs never show nan or inf.

#include "ui/number_text.h"

#include "tests/support/catch.h"

#include <limits>

using linkwright::ui::numberText;
using linkwright::ui::pointText;

TEST_CASE("read-outs show numbers as the core's number text does, and undefined for the rest", "[ui][number_text]") {
  CHECK(numberText(25.2149, 'f', 1) == "25.2");
  CHECK(numberText(1.5e-7) == "1.5e-07");
  CHECK(numberText(std::numeric_limits<double>::quiet_NaN(), 'f', 2) == "undefined");
  CHECK(numberText(-std::numeric_limits<double>::infinity()) == "undefined");
  // A value that rounds to zero shows no sign that is not there (QString::number wrote "-0.00").
  CHECK(numberText(-0.0001, 'f', 2) == "0.00");
  CHECK(numberText(-0.0) == "0");
}

TEST_CASE("a point's round-off coordinate reads 0, a small real one does not", "[ui][number_text]") {
  // Issue 57 item 10: a cognate's pivot read "(30, 2.548e-15) mm".
  CHECK(pointText(30.0, 2.548e-15, 5) == "(30, 0)");
  CHECK(pointText(-1e-17, -4.25, 3) == "(0, -4.25)");
  CHECK(pointText(30.0, 0.001, 5) == "(30, 0.001)");
  CHECK(pointText(1e-9, 2e-9) == "(1e-09, 2e-09)");
  CHECK(pointText(0.0, 0.0) == "(0, 0)");
  CHECK(pointText(std::numeric_limits<double>::quiet_NaN(), 1.0) == "(undefined, 1)");
}
