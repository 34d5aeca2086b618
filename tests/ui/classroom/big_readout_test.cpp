// The big read-out (ui/classroom/big_readout.h): its numbers are the document's pose's, read
// through the core, at each crank angle it is moved to; a rate that does not exist at a toggle
// reads "—"; a slider-crank shows its piston.

#include "ui/classroom/big_readout.h"
#include "ui/document/mechanism_document.h"

#include "tests/ui/support/four_bar_design.h"

#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::ui;
namespace k = linkwright::kinematics;
namespace fourbar = linkwright::kinematics::fourbar;

// Catch prints QStrings as text.
namespace Catch {
template <>
struct StringMaker<QString> {
  static std::string convert(const QString& s) { return '"' + s.toStdString() + '"'; }
};
}  // namespace Catch

namespace {

// The expected text, written independently of the read-out's formatting: fixed decimals and a
// true minus sign.
QString fixed(double value, int decimals) {
  return QString::number(value, 'f', decimals).replace(QLatin1Char('-'), QChar(0x2212));
}

QString degrees(double deg) { return fixed(deg, 1) + QChar(0x00B0); }

QStringList symbols(const std::vector<ReadoutEntry>& entries) {
  QStringList out;
  for (const ReadoutEntry& e : entries) out << e.symbol;
  return out;
}

}  // namespace

TEST_CASE("the big read-out gives the pose's values at each crank angle it moves to", "[ui][classroom][readout]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("thesis-crank-rocker"));
  BigReadout readout(&doc);
  readout.show();  // off screen it only catches up when shown
  REQUIRE(symbols(readout.entries()) == QStringList{"θ2", "θ4", "ω4", "μ"});
  QString before = readout.text();
  // 120° and 250°: the rocker's angle on either side of 180°, ω4 of both signs.
  for (const double deg : {120.0, 250.0}) {
    CAPTURE(deg);
    doc.setCrankAngle(k::degToRad(deg));  // a crank move: the read-out follows by itself
    REQUIRE(doc.poseStatus() == k::PoseStatus::Ok);
    const k::Pose& p = doc.pose();
    // The core's pose in the read-out's convention: angles in (0°, 360°], ω in rad/s.
    double theta4 = k::radToDeg(p.linkAngle[fourbar::kRocker.index]);
    theta4 -= 360.0 * std::ceil(theta4 / 360.0 - 1.0);
    const auto& e = readout.entries();
    CHECK(e[0].value == degrees(deg));
    CHECK(e[1].value == degrees(theta4));
    CHECK(e[2].value == fixed(k::radToDeg(p.linkOmega[fourbar::kRocker.index]), 1) + " deg/s");  // the plots' default
    CHECK(e[3].value == degrees(k::radToDeg(p.transmissionAngle[fourbar::kC.index])));
    CHECK(
        readout.text() ==
        QStringLiteral("θ2 = %1    θ4 = %2    ω4 = %3    μ = %4").arg(e[0].value, e[1].value, e[2].value, e[3].value));
    CHECK(readout.text() != before);
    before = readout.text();
  }
  SECTION("in the plots' radians") {
    readout.setAngleUnit(AngleUnit::Radians);
    const k::Pose& p = doc.pose();
    CHECK(readout.entries()[0].value == fixed(doc.crankAngle(), 3) + " rad");
    CHECK(readout.entries()[2].value == fixed(p.linkOmega[fourbar::kRocker.index], 2) + " rad/s");
  }
}

TEST_CASE("at a toggle the big read-out gives the angles and a dash for ω", "[ui][classroom][readout]") {
  MechanismDocument doc;
  doc.reset(linkwright::testing::fourBar({40.0, 30.0, 20.0, 25.0}));  // non-Grashof: it stops at toggles
  BigReadout readout(&doc);
  readout.show();  // off screen it only catches up when shown
  doc.setCrankAngle(doc.analysis().inputRange.ranges[0].to);
  REQUIRE(doc.poseStatus() == k::PoseStatus::Singular);
  REQUIRE(symbols(readout.entries()) == QStringList{"θ2", "θ4", "ω4", "μ"});
  CHECK(readout.entries()[2].value == QString(QChar(0x2014)));
  for (const std::size_t i : {0, 1, 3}) {
    CAPTURE(i);
    CHECK(readout.entries()[i].value.endsWith(QChar(0x00B0)));  // a number, not a dash
  }
  CHECK_FALSE(readout.text().contains("nan", Qt::CaseInsensitive));
  CHECK_FALSE(readout.text().contains("inf", Qt::CaseInsensitive));
}

TEST_CASE("a slider-crank's big read-out gives the piston's position and velocity", "[ui][classroom][readout]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("ls3-engine"));
  BigReadout readout(&doc);
  readout.show();  // off screen it only catches up when shown
  doc.setCrankAngle(k::degToRad(60.0));
  REQUIRE(doc.poseStatus() == k::PoseStatus::Ok);
  const auto& e = readout.entries();
  REQUIRE(symbols(e) == QStringList{"θ2", "C x", "C vx", "μ"});
  const k::Pose& p = doc.pose();
  const std::size_t c = k::slidercrank::kC.index;  // the piston pin
  CHECK(e[1].value == fixed(p.position[c].x(), 1) + " mm");
  CHECK(e[2].value == fixed(p.velocity[c].x(), 1) + " mm/s");
}

TEST_CASE("a hidden big read-out computes nothing and catches up when shown", "[ui][classroom][readout]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("thesis-crank-rocker"));
  BigReadout readout(&doc);
  readout.show();
  doc.setCrankAngle(k::degToRad(120.0));
  const QString at120 = readout.text();
  readout.hide();
  doc.reset(*k::designForExample("ls3-engine"));  // another linkage, other quantities
  doc.setCrankAngle(k::degToRad(60.0));
  CHECK(readout.text() == at120);  // untouched while hidden
  readout.show();
  REQUIRE(symbols(readout.entries()) == QStringList{"θ2", "C x", "C vx", "μ"});
  CHECK(readout.entries()[0].value == degrees(60.0));
}
