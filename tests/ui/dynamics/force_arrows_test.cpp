// Force arrows: one per joint at the current pose, the largest force of the cycle drawn
// kForceArrowLengthPx long, each labelled with its magnitude in N; none without forces.
#include "ui/canvas/force_arrows_item.h"
#include "ui/canvas/label_item.h"

#include "ui/document/force_results.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <QGraphicsScene>

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

TEST_CASE("force arrows point along the joint forces, scaled to the cycle's peak", "[forces][canvas]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("funsho-fourbar"));
  ForceResults forces(&doc);
  ForceArrowsItem arrows;
  arrows.setForces(doc, forces);
  for (const ForceArrowItem* a : arrows.arrows()) CHECK_FALSE(a->isVisible());

  forces.setEnabled(true);
  arrows.setForces(doc, forces);
  const k::PoseForces& f = *forces.poseForces();
  REQUIRE(arrows.arrows().size() == f.revolute.size());
  for (std::size_t i = 0; i < f.revolute.size(); ++i) {
    const ForceArrowItem* a = arrows.arrows()[i];
    CAPTURE(i);
    CHECK(a->isVisible());
    CHECK(a->lengthPx() == Approx(kForceArrowLengthPx * f.revolute[i].norm() / forces.peakJointForce()));
    CHECK(a->lengthPx() <= kForceArrowLengthPx);
    const Eigen::Vector2d unit = f.revolute[i].normalized();
    CHECK(a->direction().x() == Approx(unit.x()));
    CHECK(a->direction().y() == Approx(unit.y()));
    CHECK(a->label() == formatForce(f.revolute[i].norm()) + " N");
    const Eigen::Vector2d& at = doc.pose().position[forces.bodies()->revolutes[i].point.index];
    CHECK(a->pos() == QPointF(at.x(), at.y()));
  }
}

namespace {

// The funsho four-bar with masses at `crankDeg`, its forces solved.
struct FunshoForces {
  MechanismDocument doc;
  ForceResults forces{&doc};
  explicit FunshoForces(double crankDeg) {
    doc.reset(*k::designForExample("funsho-fourbar"));
    doc.setCrankAngle(k::degToRad(crankDeg));
    forces.setEnabled(true);
  }
};

}  // namespace

// The funsho four-bar's crank is a tenth of its frame: zoomed out, the arrows at O2 and B (forces
// alike) end in the same place, and their labels were drawn over each other ("424 N" on
// "415 N"). At the canvas's scale each label is moved beside its tip or out along its arrow
// until clear.
TEST_CASE("force arrows' labels are kept apart at the canvas's scale", "[forces][canvas]") {
  const FunshoForces f(30.0);
  ForceArrowsItem arrows;
  arrows.setForces(f.doc, f.forces);
  const auto boxes = [&](double pixelsPerUnit) {
    std::vector<QRectF> out;
    for (const ForceArrowItem* a : arrows.arrows())
      if (a->isVisible()) out.push_back(a->labelRect(QTransform::fromScale(pixelsPerUnit, -pixelsPerUnit)));
    return out;
  };
  const auto overlapping = [](const std::vector<QRectF>& b) {
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < b.size(); ++i)
      for (std::size_t j = i + 1; j < b.size(); ++j) pairs += b[i].intersects(b[j]) ? 1 : 0;
    return pairs;
  };
  for (const double scale : {1.0, 1.5, 3.0}) {
    CAPTURE(scale);
    arrows.setViewScale(0.0);  // labels where they fall
    const std::size_t before = overlapping(boxes(scale));
    arrows.setViewScale(scale);
    CHECK(overlapping(boxes(scale)) == 0);
    if (scale == 1.0) CHECK(before > 0);  // the case the canvas showed
  }
  // Zoomed in the feet are far apart: nothing is moved.
  arrows.setViewScale(0.0);
  const std::vector<QRectF> unmoved = boxes(40.0);
  arrows.setViewScale(40.0);
  CHECK(boxes(40.0) == unmoved);
}

// A short arrow's label fell on its joint's name ("C" under "13.9 N"): the scene's other labels
// are kept clear too.
TEST_CASE("force arrows' labels keep off the points' names", "[forces][canvas]") {
  const FunshoForces f(120.0);
  QGraphicsScene scene;
  auto* arrows = new ForceArrowsItem;
  scene.addItem(arrows);
  arrows->setForces(f.doc, f.forces);
  std::vector<LabelItem*> names;
  for (const ForceArrowItem* a : arrows->arrows()) {
    // A name where the canvas puts one: just above and right of the joint.
    auto* name = new LabelItem;
    name->setText(QStringLiteral("C"));
    name->setPos(a->pos());
    name->placeToward(QPointF(1.0, 1.0), 6.0);
    scene.addItem(name);
    names.push_back(name);
  }
  const double scale = 12.0;  // px per mm: the 1366×768 canvas's
  const QTransform toPixels = QTransform::fromScale(scale, -scale);
  arrows->setViewScale(scale);
  for (const ForceArrowItem* a : arrows->arrows()) {
    if (!a->isVisible()) continue;
    for (const LabelItem* name : names)
      CHECK_FALSE(a->labelRect(toPixels).intersects(name->deviceTransform(toPixels).mapRect(name->textRect())));
  }
}

// Presentation mode doubles the arrows (240 px for the largest force), more than a projector's
// canvas (570 × 378 px) holds with the labels: the largest takes at most 0.3 of its smaller side.
TEST_CASE("force arrows fit a small canvas", "[forces][canvas]") {
  const FunshoForces f(0.0);
  ForceArrowsItem arrows;
  arrows.setPresentationScale(2.0);
  arrows.setForces(f.doc, f.forces);
  std::vector<double> free;
  for (const ForceArrowItem* a : arrows.arrows()) free.push_back(a->lengthPx());
  arrows.setCanvasSize(QSizeF(570.0, 378.0));
  arrows.setForces(f.doc, f.forces);
  // Each in proportion: the cycle's largest force, 240 px free, is 0.3 · 378 px.
  for (std::size_t i = 0; i < free.size(); ++i) {
    CHECK(arrows.arrows()[i]->lengthPx() ==
          Approx(free[i] * kForceArrowCanvasShare * 378.0 / (2.0 * kForceArrowLengthPx)));
    CHECK(arrows.arrows()[i]->lengthPx() <= kForceArrowCanvasShare * 378.0);
  }
}
