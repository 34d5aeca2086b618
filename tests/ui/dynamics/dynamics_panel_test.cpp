// The dynamics panel: it shows the design's masses (the core's defaults in grey where unset),
// a mass typed in a cell is one undoable design edit, and a value the core refuses changes
// nothing and shows the core's own message.
#include "ui/panels/dynamics_panel.h"

#include "ui/document/mechanism_document.h"
#include "ui/panels/mass_table.h"

#include "kinematics/design/design.h"

#include <QCheckBox>

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <QDoubleSpinBox>

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

k::Design funsho() { return *k::designForExample("funsho-fourbar"); }
double couplerMass(const MechanismDocument& doc) { return doc.design().dynamics.links[1].mass; }

}  // namespace

TEST_CASE("the panel lists each link's mass, centre and inertia from the design", "[forces][panel]") {
  MechanismDocument doc;
  doc.reset(funsho());
  DynamicsPanel panel(&doc);
  MassTable* t = panel.linkTable();
  REQUIRE(t->rowCount() == 3);
  CHECK(t->item(1, 0)->text() == "coupler");
  CHECK(t->item(1, 1)->text() == "0.6");
  CHECK(t->item(1, 2)->text() == "17.5");
  CHECK(t->item(1, 4)->text() == "0.0004");
  CHECK(t->horizontalHeaderItem(2)->text() == "Centre\nalong\n[mm]");
  CHECK(panel.sliderTable()->rowCount() == 0);

  doc.reset(linkwright::testing::fourBar());  // no masses: the core's defaults, shown as such
  CHECK(t->item(0, 1)->text() == "0");
  CHECK(t->item(0, 2)->text() == "midpoint");
  CHECK(t->item(0, 4)->text() == "m·L²/12");
}

TEST_CASE("a mass edit goes through the undo stack and undo restores it", "[forces][panel]") {
  MechanismDocument doc;
  doc.reset(funsho());
  DynamicsPanel panel(&doc);
  const int steps = doc.undoStack()->count();
  panel.linkTable()->item(1, 1)->setText("0.9");
  CHECK(couplerMass(doc) == 0.9);
  CHECK(doc.undoStack()->count() == steps + 1);
  CHECK(doc.undoStack()->undoText() == "Change mass of coupler");
  CHECK(panel.refusalMessage().isEmpty());
  doc.undoStack()->undo();
  CHECK(couplerMass(doc) == 0.6);
  CHECK(panel.linkTable()->item(1, 1)->text() == "0.6");
}

TEST_CASE("a negative mass is refused with the core's message and the design is unchanged", "[forces][panel][errors]") {
  MechanismDocument doc;
  doc.reset(funsho());
  DynamicsPanel panel(&doc);
  const k::Design before = doc.design();
  k::Design candidate = doc.design();
  candidate.dynamics.links[1].mass = -1.0;
  const std::string core = k::checkDesign(candidate)->message;
  panel.linkTable()->item(1, 1)->setText("-1");
  CHECK(doc.design() == before);
  CHECK(doc.undoStack()->count() == 0);
  CHECK(panel.refusalMessage() == QString::fromStdString(core));
  CHECK(panel.refusalMessage().contains("mass"));
  CHECK(panel.linkTable()->item(1, 1)->text() == "0.6");  // snapped back
}

TEST_CASE("clearing an inertia returns it to the core's default, gravity switches on downward", "[forces][panel]") {
  MechanismDocument doc;
  doc.reset(funsho());
  DynamicsPanel panel(&doc);
  panel.linkTable()->item(2, 4)->setText("");
  CHECK_FALSE(doc.design().dynamics.links[2].inertia.has_value());
  CHECK(panel.linkTable()->item(2, 4)->text() == "m·L²/12");
  panel.gravityBox()->setChecked(true);
  REQUIRE(doc.design().dynamics.loads.gravity.has_value());
  CHECK(*doc.design().dynamics.loads.gravity == Eigen::Vector2d(0.0, -k::kStandardGravity));
  doc.undoStack()->undo();
  CHECK_FALSE(doc.design().dynamics.loads.gravity.has_value());
  CHECK_FALSE(panel.gravityBox()->isChecked());
}

// On a projector's 1024×768 screen the side column holds about 255 px. The loads' rows side by
// side, ±1e9 N·m spin boxes sized for their longest text and the springs' two ends on one row
// made the panel 498 px wide, and the page scrolled sideways. Every input keeps its own least
// size (the screens journey checks that).
TEST_CASE("the forces panel fits a projector's side column", "[forces]") {
  for (const char* example : {"funsho-fourbar", "watt-ii", "ls3-engine"}) {
    CAPTURE(example);
    MechanismDocument doc;
    doc.reset(*k::designForExample(example));
    DynamicsPanel panel(&doc);
    CHECK(panel.minimumSizeHint().width() <= 255);
    // A number field may shrink, but not below the text it shows.
    QDoubleSpinBox* torque = panel.torqueSpin();
    CHECK(torque->sizePolicy().horizontalPolicy() == QSizePolicy::Preferred);
    CHECK(torque->minimumSizeHint().width() < torque->sizeHint().width());
    CHECK(torque->minimumSizeHint().width() >= torque->fontMetrics().horizontalAdvance(torque->text()));
  }
}
