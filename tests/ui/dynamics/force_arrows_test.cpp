// Force arrows: one per joint at the current pose, the largest force of the cycle drawn
// kForceArrowLengthPx long, each labelled with its magnitude in N; none without forces.
#include "ui/canvas/force_arrows_item.h"

#include "ui/document/force_results.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/design/design.h"

#include "tests/support/catch.h"

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
