// ui/number_text.h: the GUI's read-outs never show nan or inf.

#include "ui/number_text.h"

#include "tests/support/catch.h"

#include <limits>

using linkwright::ui::numberText;

TEST_CASE("read-outs show numbers as the core's number text does, and undefined for the rest", "[ui][number_text]") {
  CHECK(numberText(25.2149, 'f', 1) == "25.2");
  CHECK(numberText(1.5e-7) == "1.5e-07");
  CHECK(numberText(std::numeric_limits<double>::quiet_NaN(), 'f', 2) == "undefined");
  CHECK(numberText(-std::numeric_limits<double>::infinity()) == "undefined");
  // A value that rounds to zero shows no sign that is not there (QString::number wrote "-0.00").
  CHECK(numberText(-0.0001, 'f', 2) == "0.00");
  CHECK(numberText(-0.0) == "0");
}
