// The drive panel (ui/panels/drive_panel.h): choosing a motion law or typing one of its numbers
// is one undoable design edit; a value outside what is accepted is refused with a message
// naming the field, the value and the range, and the design stays as it was.

#include "ui/panels/drive_panel.h"
#include "ui/document/mechanism_document.h"
#include "ui/settings.h"

#include "kinematics/model/units.h"

#include "tests/ui/support/four_bar_design.h"
#include "tests/ui/support/timed_design.h"

#include "tests/support/catch.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTemporaryDir>
#include <QTest>

using namespace linkwright;
using Drive = ui::DrivePanel::Drive;
using Field = ui::DrivePanel::Field;
namespace k = kinematics;

namespace {

void typeInto(QDoubleSpinBox* spin, double value) {
  spin->setFocus();
  spin->selectAll();
  QTest::keyClicks(spin, QString::number(value));
  QTest::keyClick(spin, Qt::Key_Return);
}

void choose(ui::DrivePanel& panel, Drive drive) { panel.lawBox()->setCurrentIndex(static_cast<int>(drive)); }

}  // namespace

TEST_CASE("choosing a cycloidal rise gives the design that law, and undo restores the grid", "[ui][panels][law]") {
  ui::MechanismDocument doc;
  ui::Settings settings;
  ui::DrivePanel drive(&doc, &settings);
  const k::Design before = doc.design();
  REQUIRE_FALSE(before.time.has_value());
  choose(drive, Drive::CycloidalRise);
  REQUIRE(doc.design().time.has_value());
  const auto* law = std::get_if<k::CycloidalRise>(&doc.design().time->law);
  REQUIRE(law != nullptr);
  // From the grid's start over its span (a full turn) in 1 s, analysed over the rise.
  CHECK(law->start == k::degToRad(before.fromDeg));
  CHECK(law->rise == k::degToRad(before.toDeg - before.fromDeg));
  CHECK(law->duration == 1.0);
  CHECK(doc.design().time->fromTime == 0.0);
  CHECK(doc.design().time->toTime == 1.0);
  CHECK(doc.design().samples == before.samples);
  CHECK(doc.undoStack()->count() == 1);
  CHECK(doc.plotAxis() == ui::PlotAxis::Time);
  CHECK(drive.axisBox()->currentIndex() == 0);

  typeInto(drive.fieldBox(Field::Duration), 0.5);
  CHECK(std::get<k::CycloidalRise>(doc.design().time->law).duration == 0.5);
  CHECK(doc.undoStack()->count() == 2);

  doc.undoStack()->undo();
  CHECK(std::get<k::CycloidalRise>(doc.design().time->law).duration == 1.0);
  CHECK(drive.fieldBox(Field::Duration)->value() == 1.0);
  doc.undoStack()->undo();
  CHECK(doc.design() == before);
  CHECK(drive.lawBox()->currentIndex() == static_cast<int>(Drive::AngleGrid));
  CHECK(doc.plotAxis() == ui::PlotAxis::Input);
}

TEST_CASE("each law shows its own fields and sets them in the core's units", "[ui][panels][law]") {
  ui::MechanismDocument doc;
  ui::Settings settings;
  settings.setSpeedInRpm(true);
  ui::DrivePanel drive(&doc, &settings);
  drive.show();
  choose(drive, Drive::RampToSpeed);
  CHECK(drive.fieldBox(Field::RampTime)->isVisible());
  CHECK_FALSE(drive.fieldBox(Field::Rise)->isVisible());
  CHECK_FALSE(drive.fieldBox(Field::Acceleration)->isVisible());
  drive.fieldBox(Field::Speed)->setValue(60.0);  // rpm
  drive.fieldBox(Field::Start)->setValue(90.0);  // degrees
  drive.fieldBox(Field::RampTime)->setValue(0.25);
  const auto& ramp = std::get<k::RampToSpeed>(doc.design().time->law);
  CHECK(ramp.velocity == Approx(2.0 * k::kPi).margin(1e-12));
  CHECK(ramp.start == Approx(k::kPi / 2.0).margin(1e-15));
  CHECK(ramp.rampTime == 0.25);
  drive.fieldBox(Field::ToTime)->setValue(3.0);
  CHECK(doc.design().time->toTime == 3.0);

  choose(drive, Drive::AngleGrid);  // back to the grid at the speed the ramp reached
  CHECK_FALSE(doc.design().time.has_value());
  CHECK(doc.design().omega == Approx(2.0 * k::kPi).margin(1e-12));
  CHECK(drive.fieldBox(Field::Acceleration)->isVisible());
  CHECK_FALSE(drive.fieldBox(Field::FromTime)->isVisible());
}

TEST_CASE("a drive field outside its range is refused with its name, value and range, and nothing changes",
          "[ui][panels][law][errors]") {
  ui::MechanismDocument doc;
  doc.reset(testing::cycloidalFourBar());
  ui::Settings settings;
  ui::DrivePanel drive(&doc, &settings);
  const k::Design before = doc.design();

  drive.fieldBox(Field::Duration)->setValue(0.0);
  CHECK(doc.design() == before);
  CHECK(doc.undoStack()->count() == 0);
  CHECK(drive.refusalMessage() == "Not applied: Duration must be positive and at most 1e6 s (got 0 s)");
  CHECK(drive.fieldBox(Field::Duration)->value() == testing::kRiseDuration);  // snapped back

  drive.fieldBox(Field::ToTime)->setValue(-1.0);
  CHECK(doc.design() == before);
  CHECK(drive.refusalMessage() == "Not applied: To time must be after the from time, 0 s (got -1 s)");
  CHECK(drive.fieldBox(Field::ToTime)->value() == testing::kRiseDuration);

  drive.samplesBox()->setValue(1);
  CHECK(doc.design() == before);
  CHECK(drive.refusalMessage() == "Not applied: Samples must be between 2 and 100000 (got 1)");
  CHECK(drive.samplesBox()->value() == static_cast<int>(before.samples));

  // The core's own limits come back the same way: a rise this fast exceeds the largest ω.
  drive.fieldBox(Field::Rise)->setValue(900000.0);  // 2h/T = 6.3e4 rad/s: accepted
  const k::Design risen = doc.design();
  CHECK(std::get<k::CycloidalRise>(risen.time->law).rise == Approx(k::degToRad(900000.0)));
  drive.fieldBox(Field::Duration)->setValue(0.001);  // 3.1e7 rad/s: too fast
  CHECK(doc.design() == risen);
  CHECK(drive.refusalMessage().contains("law peak velocity"));
  CHECK(drive.fieldBox(Field::Duration)->value() == testing::kRiseDuration);

  // A good value afterwards is applied and clears the message.
  drive.fieldBox(Field::Duration)->setValue(0.25);
  CHECK(std::get<k::CycloidalRise>(doc.design().time->law).duration == 0.25);
  CHECK(drive.refusalMessage().isEmpty());
}

TEST_CASE("the plots' x axis is chosen in the drive panel, and time needs a time base", "[ui][panels][law]") {
  ui::MechanismDocument doc;
  ui::Settings settings;
  ui::DrivePanel drive(&doc, &settings);
  const auto* model = qobject_cast<QStandardItemModel*>(drive.axisBox()->model());
  REQUIRE(model != nullptr);
  CHECK_FALSE(model->item(0)->isEnabled());  // no time base: the input only
  CHECK(drive.axisBox()->currentIndex() == 1);
  doc.reset(testing::cycloidalFourBar());
  CHECK(model->item(0)->isEnabled());
  CHECK(drive.axisBox()->currentIndex() == 0);
  drive.axisBox()->setCurrentIndex(1);
  CHECK(doc.plotAxis() == ui::PlotAxis::Input);
  CHECK(doc.undoStack()->count() == 0);  // a view setting, not an edit
}

TEST_CASE("a θ(t) table is loaded from a CSV file, and a malformed one is refused saying why", "[ui][panels][law]") {
  QTemporaryDir dir;
  const QString good = dir.filePath("theta.csv");
  {
    QFile f(good);
    REQUIRE(f.open(QIODevice::WriteOnly));
    f.write("time_s,crank_angle_deg\n0,0\n0.25,5.625\n0.5,45\n0.75,151.875\n1,360\n");  // 360·t³
  }
  ui::MechanismDocument doc;
  ui::Settings settings;
  ui::DrivePanel drive(&doc, &settings);
  REQUIRE_FALSE(drive.loadTable(good).has_value());
  const auto& table = std::get<k::TableLaw>(doc.design().time->law);
  CHECK(table.time.size() == 5);
  CHECK(doc.design().time->fromTime == 0.0);
  CHECK(doc.design().time->toTime == 1.0);
  // A cubic is reproduced to round-off (motion_law.h).
  CHECK(k::motionAt(table, 0.6).position == Approx(k::degToRad(360.0 * 0.216)).margin(1e-12));
  CHECK(drive.lawBox()->currentIndex() == static_cast<int>(Drive::Table));

  const QString bad = dir.filePath("bad.csv");
  {
    QFile f(bad);
    REQUIRE(f.open(QIODevice::WriteOnly));
    f.write("t,angle\n0,0\n");
  }
  const k::Design before = doc.design();
  const auto why = drive.loadTable(bad);
  REQUIRE(why.has_value());
  CHECK(why->contains("must name the columns time_s"));
  CHECK(doc.design() == before);
}

TEST_CASE("driving a four-bar from its rocker keeps its pose and law kind, as one undo step", "[ui][panels][driver]") {
  ui::MechanismDocument doc;
  doc.reset(k::designForExample("thesis-crank-rocker").value());
  ui::Settings settings;
  ui::DrivePanel drive(&doc, &settings);
  doc.setCrankAngle(k::degToRad(40.0));
  const k::Design before = doc.design();
  const k::Pose pose = doc.pose();
  REQUIRE(drive.driverBox()->count() == 2);
  CHECK(drive.driverBox()->isEnabled());
  CHECK(drive.driverBox()->itemText(1) == "rocker about O4 (angle)");
  choose(drive, Drive::CycloidalRise);

  drive.driverBox()->setCurrentIndex(1);
  const k::Mechanism& m = doc.mechanism();
  CHECK(m.points[k::driverPoint(m)->index].name == "C");
  CHECK(drive.driverBox()->currentIndex() == 0);  // the driver now listed first
  CHECK(drive.driverBox()->itemText(0) == "rocker about O4 (angle)");
  CHECK(drive.lawBox()->currentIndex() == static_cast<int>(Drive::CycloidalRise));
  CHECK(doc.undoStack()->count() == 2);
  CHECK(drive.refusalMessage().isEmpty());

  doc.undoStack()->undo();
  doc.undoStack()->undo();
  CHECK(doc.design() == before);
  CHECK(doc.pose().position == pose.position);
}

TEST_CASE("driving from the rocker on a grid leaves every joint where it was", "[ui][panels][driver]") {
  ui::MechanismDocument doc;
  doc.reset(k::designForExample("thesis-crank-rocker").value());
  ui::Settings settings;
  ui::DrivePanel drive(&doc, &settings);
  doc.setCrankAngle(k::degToRad(130.0));
  const k::Pose before = doc.pose();
  const k::Mechanism old = doc.mechanism();
  drive.driverBox()->setCurrentIndex(1);
  REQUIRE(drive.refusalMessage().isEmpty());
  for (const k::Point& p : old.points) {
    INFO(p.name);
    const auto i = old.findPoint(p.name)->index;
    const auto j = doc.mechanism().findPoint(p.name)->index;
    CHECK((doc.pose().position[j] - before.position[i]).norm() < 1e-9);
  }
}

TEST_CASE("a driver that cannot take a slider's mass is refused with the core's reason",
          "[ui][panels][driver][errors]") {
  ui::MechanismDocument doc;
  k::Design ls3 = k::designForExample("ls3-engine").value();
  ls3.dynamics.sliders = {{"C", 0, 0.5, 0.0}};
  doc.reset(ls3);
  ui::Settings settings;
  ui::DrivePanel drive(&doc, &settings);
  REQUIRE(drive.driverBox()->count() == 2);
  drive.driverBox()->setCurrentIndex(1);
  CHECK(doc.design() == ls3);
  CHECK(doc.undoStack()->count() == 0);
  CHECK(drive.refusalMessage().contains("C along its guide (position)"));
  CHECK(drive.refusalMessage().contains("its carriage is massless"));
  CHECK(drive.driverBox()->currentIndex() == 0);
}

TEST_CASE("a linkage with one possible driver shows it, disabled", "[ui][panels][driver]") {
  ui::MechanismDocument doc;
  doc.reset(k::designForExample("excavator-boom").value());
  ui::Settings settings;
  ui::DrivePanel drive(&doc, &settings);
  CHECK(drive.driverBox()->count() == 1);
  CHECK_FALSE(drive.driverBox()->isEnabled());
}
