// What the scene draws for a document: items at the solved pose after design and motion
// changes, the crank's range only when it cannot turn fully, the coupler path broken at
// gaps, rate arrows to a per-design scale.

#include "canvas_test_support.h"

#include "ui/canvas/arrow_item.h"
#include "ui/canvas/coupler_path_item.h"
#include "ui/canvas/drag_handles.h"
#include "ui/canvas/feasible_range_item.h"
#include "ui/canvas/label_item.h"
#include "ui/canvas/link_item.h"
#include "ui/canvas/mass_centres_item.h"
#include "ui/canvas/springs_item.h"

#include "kinematics/dynamics/force_balance.h"
#include "kinematics/model/units.h"

#include <QGraphicsPolygonItem>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

#include "tests/support/catch.h"

namespace k = linkwright::kinematics;
namespace fourbar = linkwright::kinematics::fourbar;
using linkwright::ui::toQt;
using linkwright::ui::test::nonGrashofDesign;
using linkwright::ui::test::ShownView;

namespace {

void requireItemsAtPose(ShownView& v) {
  const auto& scene = v.scene();
  for (const auto point : {fourbar::kO2, fourbar::kO4, fourbar::kB, fourbar::kC}) {
    CAPTURE(point.index);
    CHECK(scene.handleItem(point)->pos() == v.point(point));
  }
  CHECK(scene.linkItem(fourbar::kCrank)->line() == QLineF(v.point(fourbar::kO2), v.point(fourbar::kB)));
  CHECK(scene.linkItem(fourbar::kCoupler)->line() == QLineF(v.point(fourbar::kB), v.point(fourbar::kC)));
  CHECK(scene.linkItem(fourbar::kRocker)->line() == QLineF(v.point(fourbar::kO4), v.point(fourbar::kC)));
}

int countMoveTos(const QPainterPath& path) {
  int moves = 0;
  for (int i = 0; i < path.elementCount(); ++i) moves += path.elementAt(i).isMoveTo() ? 1 : 0;
  return moves;
}

}  // namespace

TEST_CASE("items move to the new pose after a design change and after motion", "[canvas][scene]") {
  ShownView v;
  requireItemsAtPose(v);
  const QPointF cBefore = v.scene().handleItem(fourbar::kC)->pos();

  const k::Design edited = linkwright::testing::withLengths(v.document.design(), {50.0, 20.0, 65.0, 40.0});
  REQUIRE_FALSE(v.document.edit(edited, "lengths"));
  requireItemsAtPose(v);
  CHECK(v.scene().handleItem(fourbar::kC)->pos() != cBefore);
  CHECK(v.scene().handleItem(fourbar::kO4)->pos() == QPointF(50.0, 0.0));

  v.document.setCrankAngle(1.0);
  requireItemsAtPose(v);
}

TEST_CASE("the crank's range is drawn only when the crank cannot turn fully", "[canvas][scene]") {
  SECTION("thesis crank-rocker (60, 25, 70, 45): full rotation, no range") {
    ShownView v;
    REQUIRE(v.document.analysis().inputRange.fullRotation);
    CHECK_FALSE(v.scene().feasibleRangeItem()->isVisible());
  }
  SECTION("non-Grashof (40, 30, 20, 25): the range and its limits are shown") {
    ShownView v(nonGrashofDesign());
    const k::InputRange& range = v.document.analysis().inputRange;
    REQUIRE_FALSE(range.fullRotation);
    REQUIRE(range.ranges.size() == 1);
    const auto* item = v.scene().feasibleRangeItem();
    CHECK(item->isVisible());
    const QString limit = QString::number(k::radToDeg(range.ranges[0].to), 'f', 1);
    CHECK(item->labelText().startsWith("crank can reach"));
    CHECK(item->labelText().contains(limit));
    // Around O2 at the crank's length, and inside what a fit shows.
    const QRectF bounds = item->boundingRect();
    CHECK(bounds.center().x() == Approx(0.0).margin(1e-9));
    CHECK(bounds.width() > 2.0 * v.document.fourBar()->lengths.crank);
    CHECK(v.scene().contentBounds().contains(bounds));
    // Its sentence: drawn above the links, so none crosses the text, and outside the crank's
    // circle, so it covers neither O2's name nor the crank (it sat over both inside it).
    const linkwright::ui::LabelItem* label = v.scene().rangeLabelItem();
    REQUIRE(label->isVisible());
    CHECK(label->text() == item->labelText());
    CHECK(label->zValue() > v.scene().linkItem(fourbar::kCoupler)->zValue());
    const QRectF box = label->boundingRect().translated(v.pixelOf(label->scenePos()));
    const QPointF pivot = v.pixelOf(v.point(fourbar::kO2));
    const double crankPx = v.document.fourBar()->lengths.crank * v.view.transform().m11();
    const QPointF nearest(std::clamp(pivot.x(), box.left(), box.right()),
                          std::clamp(pivot.y(), box.top(), box.bottom()));
    CAPTURE(box.left(), box.top(), box.right(), box.bottom(), pivot.x(), pivot.y(), crankPx);
    CHECK(std::hypot(nearest.x() - pivot.x(), nearest.y() - pivot.y()) > crankPx);
  }
  SECTION("undoing back to a crank-rocker hides it again") {
    ShownView v;
    const k::Design design = nonGrashofDesign();
    REQUIRE_FALSE(v.document.edit(design, "lengths"));
    CHECK(v.scene().feasibleRangeItem()->isVisible());
    v.document.undoStack()->undo();
    CHECK_FALSE(v.scene().feasibleRangeItem()->isVisible());
  }
}

TEST_CASE("the coupler point, its triangle and its path follow the design", "[canvas][scene]") {
  SECTION("no coupler point: nothing drawn for it") {
    ShownView v;
    CHECK(v.scene().handleItem(fourbar::kCouplerPoint) == nullptr);
    CHECK(v.scene().pathItem(fourbar::kCouplerPoint) == nullptr);
    CHECK(v.scene().couplerTriangleItem() == nullptr);
    CHECK_FALSE(v.scene().handlePosition(fourbar::kCouplerPoint));
  }
  SECTION("full rotation: one unbroken path through every sample") {
    const k::Design design =
        k::fourBarDesign(k::kThesisCrankRocker, k::Branch::Open, "mm", k::CouplerPointSpec{35.0, 15.0}).value();
    ShownView v(design);
    const QPainterPath path = v.scene().pathItem(fourbar::kCouplerPoint)->path();
    CHECK(v.scene().pathItem(fourbar::kCouplerPoint)->isVisible());
    CHECK(countMoveTos(path) == 1);
    CHECK(path.elementCount() == static_cast<int>(v.document.sweep().size()));
    CHECK(v.scene().handleItem(fourbar::kCouplerPoint)->pos() == v.point(fourbar::kCouplerPoint));
    const QPolygonF triangle = v.scene().couplerTriangleItem()->polygon();
    REQUIRE(triangle.size() == 3);
    CHECK(triangle[2] == v.point(fourbar::kCouplerPoint));
  }
  SECTION("partial range: the path breaks where the linkage cannot be assembled") {
    const k::Design design =
        k::fourBarDesign({40.0, 30.0, 20.0, 25.0}, k::Branch::Open, "mm", k::CouplerPointSpec{10.0, 8.0}).value();
    ShownView v(design);
    REQUIRE_FALSE(v.document.sweep().notAssembled.empty());
    // The grid 0°..360° sees the range [−φ, φ] as two runs: from 0° and up to 360°.
    CHECK(countMoveTos(v.scene().pathItem(fourbar::kCouplerPoint)->path()) == 2);
  }
}

TEST_CASE("velocity and acceleration arrows", "[canvas][scene]") {
  ShownView v;
  const auto* arrowB = v.scene().velocityArrow(fourbar::kB);
  REQUIRE(arrowB != nullptr);
  CHECK_FALSE(arrowB->isVisible());

  v.view.setShowVelocityArrows(true);
  REQUIRE(arrowB->isVisible());
  const Eigen::Vector2d vb = v.document.pose().velocity[fourbar::kB.index];
  const double scale = v.scene().velocityScale();
  REQUIRE(scale > 0.0);
  CHECK(arrowB->start() == v.point(fourbar::kB));
  CHECK(arrowB->vector() == scale * toQt(vb));
  CHECK(arrowB->label() == QString::number(vb.norm(), 'f', 1) + " mm/s");  // |vB| = 25 mm/s at ω = 1
  CHECK_FALSE(v.scene().accelerationArrow(fourbar::kC)->isVisible());

  SECTION("the scale is fixed per design: the longest arrow of the cycle is 0.3 of the linkage") {
    double longest = 0.0;
    const auto& sweep = v.document.sweep();
    for (const auto id : {fourbar::kB, fourbar::kC})
      for (std::size_t j = 0; j < sweep.size(); ++j) longest = std::max(longest, sweep.velocity[id.index][j].norm());
    CHECK(scale * longest == Approx(0.3 * v.scene().linkageSize()));
    v.document.setCrankAngle(2.0);
    CHECK(v.scene().velocityScale() == scale);
    CHECK(arrowB->start() == v.point(fourbar::kB));
  }
  SECTION("acceleration arrows carry their unit") {
    v.view.setShowAccelerationArrows(true);
    const auto* arrowC = v.scene().accelerationArrow(fourbar::kC);
    CHECK(arrowC->isVisible());
    CHECK(arrowC->label().endsWith(QString::fromUtf8("mm/s²")));
  }
  SECTION("hidden at a toggle position, where rates do not exist") {
    v.document.reset(nonGrashofDesign());
    v.document.setCrankAngle(v.document.analysis().inputRange.ranges[0].to);
    REQUIRE(v.document.poseStatus() == k::PoseStatus::Singular);
    CHECK_FALSE(v.scene().velocityArrow(fourbar::kB)->isVisible());
    CHECK_FALSE(v.scene().velocityArrow(fourbar::kC)->isVisible());
  }
}

TEST_CASE("presentation scale thickens links and enlarges pins", "[canvas][scene]") {
  ShownView v;
  const double width = v.scene().linkItem(fourbar::kCrank)->pen().widthF();
  v.view.setPresentationScale(2.0);
  CHECK(v.scene().linkItem(fourbar::kCrank)->pen().widthF() == Approx(2.0 * width));
  CHECK(v.scene().handleItem(fourbar::kB)->scale() == 2.0);
  CHECK(v.scene().handleItem(fourbar::kO2)->scale() == 2.0);
  CHECK(v.scene().linkItem(fourbar::kCrank)->pen().isCosmetic());
}

TEST_CASE("a spring is drawn between its ends at the pose, and leaves with the design", "[canvas][scene][springs]") {
  k::Design design = *k::designForExample("funsho-fourbar");
  design.mechanism.points.push_back({"S", k::GroundPoint{Eigen::Vector2d(-10.0, 25.0)}});
  design.dynamics.loads.springs = {{"lift", {"rocker", "C"}, {"", "S"}, 500.0, 10.0, 0.0}};
  ShownView v(design);
  const auto* springs = v.scene().springsItem();
  REQUIRE(springs->isVisible());
  const auto ends = [&] {
    const QPainterPath& path = springs->path();
    REQUIRE(path.elementCount() == 2 * 8 + 4);  // a lead, sixteen coil corners, a lead
    return std::pair{QPointF(path.elementAt(0)), QPointF(path.elementAt(path.elementCount() - 1))};
  };
  const k::PointId c = *design.mechanism.findPoint("C"), s = *design.mechanism.findPoint("S");
  CHECK(ends() == std::pair{v.point(c), v.point(s)});
  v.document.setCrankAngle(k::degToRad(120.0));
  CHECK(ends() == std::pair{v.point(c), v.point(s)});  // it follows the crank
  v.document.reset(*k::designForExample("funsho-fourbar"));
  CHECK_FALSE(springs->isVisible());
  CHECK(springs->path().isEmpty());
}

TEST_CASE("each link's centre of mass is drawn where the core puts it, a counterweight's behind its pivot",
          "[canvas][scene][masses]") {
  k::Design design = *k::designForExample("funsho-fourbar");
  design.dynamics = k::balanceShakingForce(design.mechanism, design.dynamics)->balanced;
  ShownView v(design);
  const auto* masses = v.scene().massCentresItem();
  REQUIRE(masses->isVisible());
  const auto expected = [&](std::size_t k) {
    const k::LinkMass& mass = design.dynamics.links[k];
    const k::Link& link = design.mechanism.links[design.mechanism.findLink(mass.link)->index];
    const Eigen::Vector2d c = k::massCentreAt(mass, v.document.pose().position[link.first.index],
                                              v.document.pose().position[link.second.index]);
    return QPointF(c.x(), c.y());
  };
  for (const double deg : {0.0, 120.0}) {
    v.document.setCrankAngle(k::degToRad(deg));
    REQUIRE(masses->centres().size() == 3);
    for (std::size_t k = 0; k < 3; ++k) CHECK(masses->centres()[k] == expected(k));
  }
  // The crank's counterweight puts its centre behind O2, away from B.
  const k::PointId o2 = *design.mechanism.findPoint("O2"), b = *design.mechanism.findPoint("B");
  const QPointF toB = v.point(b) - v.point(o2), toCentre = masses->centres()[0] - v.point(o2);
  CHECK(QPointF::dotProduct(toB, toCentre) < 0.0);
  v.document.reset(*k::designForExample("thesis-crank-rocker"));  // no masses
  CHECK_FALSE(masses->isVisible());
  CHECK(masses->centres().empty());
}
