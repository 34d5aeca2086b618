// Tests ui/plots/hover_readout.h: the read-out sentence and its numbers.
#include "ui/plots/hover_readout.h"

#include "four_bar_curves.h"

#include "tests/support/catch.h"

using namespace linkwright::ui;
using linkwright::ui::test::fourBarCurve;
using linkwright::ui::test::fourBarQuantities;

TEST_CASE("Read-out numbers keep about three significant digits", "[hover_readout]") {
  CHECK(formatReadoutNumber(0.6191) == "0.619");
  CHECK(formatReadoutNumber(-12.345) == "-12.3");
  CHECK(formatReadoutNumber(131.81) == "131.8");
  CHECK(formatReadoutNumber(0.0) == "0.00");
  CHECK(formatReadoutNumber(0.000123456) == "0.000123");
}

TEST_CASE("The read-out names the curve, the value with its unit and the crank angle", "[hover_readout]") {
  CHECK(readoutText(fourBarCurve(PlotQuantity::RockerOmega), {1.5708, 0.619}, AngleUnit::Radians) ==
        QStringLiteral("rocker ω4 = 0.619 rad/s at crank 1.571 rad"));
  CHECK(readoutText(fourBarCurve(PlotQuantity::RockerOmega), {90.0, 35.47}, AngleUnit::Degrees) ==
        QStringLiteral("rocker ω4 = 35.5 deg/s at crank 90.0°"));
  CHECK(readoutText(fourBarCurve(PlotQuantity::CouplerAlpha), {90.0, -2.5}, AngleUnit::Radians) ==
        QStringLiteral("coupler α3 = -2.50 rad/s² at crank 90.000 rad"));
  CHECK(readoutText(fourBarCurve(PlotQuantity::TransmissionAngle), {228.2, 48.19}, AngleUnit::Degrees) ==
        QStringLiteral("transmission μ = 48.2° at crank 228.2°"));
}

TEST_CASE("The read-out label shows a point and goes back to its hint", "[hover_readout]") {
  HoverReadout readout;
  const QString hint = readout.text();
  readout.showPoint(fourBarCurve(PlotQuantity::CouplerAngle), {10.0, 20.0}, AngleUnit::Degrees, QStringLiteral("mm"),
                    true);
  CHECK(readout.text() == QStringLiteral("coupler θ3 = 20.0° at crank 10.0°"));
  readout.showPoint(fourBarCurve(PlotQuantity::CouplerAngle), {10.0, 20.0}, AngleUnit::Degrees, QStringLiteral("mm"),
                    false);
  CHECK(readout.text() == hint);
}
