// The canvas with linkages other than four-bars: a handle on every point but a PRP pin, a
// slider as a block on its slideway, a slotted link with its block, plates for links that
// carry points, and a mouse drag that goes through dragPoint and undoes exactly.

#include "canvas_test_support.h"

#include "ui/canvas/label_item.h"
#include "ui/canvas/link_item.h"
#include "ui/canvas/slider_block_item.h"
#include "ui/canvas/slideway_item.h"
#include "ui/canvas/slotted_link_item.h"

#include "kinematics/design/dyad_request.h"
#include "kinematics/design/point_drag.h"
#include "kinematics/solve/pose_solver.h"

#include <QGraphicsPolygonItem>
#include <QSignalSpy>

#include "tests/support/catch.h"

#include <cmath>

namespace k = linkwright::kinematics;
namespace ui = linkwright::ui;
using linkwright::ui::toEigen;
using linkwright::ui::toQt;
using linkwright::ui::test::ShownView;

namespace {

k::Design example(const std::string& name) { return *k::designForExample(name); }

// Distance of `p` from the line through `a` and `b`, scene units.
double offLine(const QPointF& p, const QLineF& line) {
  const QPointF d = line.p2() - line.p1();
  return std::abs(d.x() * (p.y() - line.p1().y()) - d.y() * (p.x() - line.p1().x())) / std::hypot(d.x(), d.y());
}

}  // namespace

TEST_CASE("every point of a linkage but a PRP pin has a handle, at its solved position", "[canvas][linkage]") {
  for (const std::string name :
       {"ls3-engine", "shaper", "whitworth", "watt-i", "watt-ii", "stephenson-i", "stephenson-iii"}) {
    CAPTURE(name);
    ShownView v(example(name));
    const std::size_t points = v.document.mechanism().points.size();
    CHECK(v.scene().handles().size() == points);
    for (std::size_t i = 0; i < points; ++i) {
      CAPTURE(i);
      const QGraphicsItem* handle = v.scene().handleItem(k::PointId{i});
      REQUIRE(handle != nullptr);
      CHECK(handle->pos() == v.point(k::PointId{i}));
      CHECK(v.scene().pointLabel(k::PointId{i})->text() == ui::pointDisplayName(v.document.mechanism().points[i].name));
    }
  }
}

TEST_CASE("a slider is a block on a hatched slideway that spans its stroke", "[canvas][linkage]") {
  ShownView v(example("ls3-engine"));
  const k::PointId piston{2};
  const auto* block = v.scene().sliderBlock(piston);
  const auto* way = v.scene().slideway(piston);
  REQUIRE(block != nullptr);
  REQUIRE(way != nullptr);
  CHECK(way->onGround());
  CHECK(block->pos() == v.point(piston));
  CHECK(block->direction() == QPointF(1.0, -0.0));  // along +x; item pixels have y down
  const QLineF line = way->line();
  double lowest = 1e300, highest = -1e300;
  const auto& sweep = v.document.sweep();
  for (std::size_t j = 0; j < sweep.size(); ++j) {
    lowest = std::min(lowest, sweep.position[piston.index][j].x());
    highest = std::max(highest, sweep.position[piston.index][j].x());
  }
  CHECK(std::min(line.x1(), line.x2()) < lowest);
  CHECK(std::max(line.x1(), line.x2()) > highest);
  CHECK(line.y1() == 0.0);
  CHECK(line.y2() == 0.0);
  v.document.setCrankAngle(2.0);
  CHECK(block->pos() == v.point(piston));
  CHECK(v.scene().contentBounds().contains(line.p1()));
}

TEST_CASE("a slotted link is a bar with a slot along it and a block at the crank pin", "[canvas][linkage]") {
  ShownView v(example("shaper"));
  const auto* slotted = v.scene().slottedLinkItem(k::LinkId{1});
  REQUIRE(slotted != nullptr);
  CHECK(v.scene().linkItem(k::LinkId{1}) == nullptr);  // the bar is the slotted item
  for (const double angle : {0.0, 1.0, 2.5, 4.0}) {
    CAPTURE(angle);
    v.document.setCrankAngle(angle);
    const QPointF pivot = v.point(k::PointId{1}), pin = v.point(k::PointId{2}), tip = v.point(k::PointId{3});
    CHECK(slotted->bar().p1() == pivot);
    CHECK(QLineF(pivot, slotted->bar().p2()).length() >= QLineF(pivot, tip).length() - 1e-9);
    // The pin lies on the slot, within its ends.
    CHECK(offLine(pin, slotted->slot()) < 1e-9 * 400.0);
    const double along = QLineF(pivot, pin).length();
    CHECK(along > QLineF(pivot, slotted->slot().p1()).length());
    CHECK(along < QLineF(pivot, slotted->slot().p2()).length());
  }
}

TEST_CASE("a link that carries points is a plate over its corners", "[canvas][linkage]") {
  ShownView v(example("watt-i"));
  const auto* coupler = v.scene().bodyItem(k::LinkId{1});
  REQUIRE(coupler != nullptr);
  const QPolygonF corners = coupler->polygon();
  REQUIRE(corners.size() == 3);
  CHECK(corners[0] == v.point(k::PointId{2}));  // B
  CHECK(corners[1] == v.point(k::PointId{3}));  // C
  CHECK(corners[2] == v.point(k::PointId{4}));  // P
  CHECK(v.scene().pathItem(k::PointId{4}) != nullptr);
  CHECK(v.scene().bodyItem(k::LinkId{0}) == nullptr);  // the crank carries nothing here
}

TEST_CASE("dragging a linkage's joint with the mouse goes through dragPoint and undoes exactly",
          "[canvas][linkage][drag]") {
  ShownView v(example("watt-ii"));
  const k::Design before = v.document.design();
  const k::PointId e{6};
  const QPointF grabbed = v.point(e);
  const QPoint press = v.pixelOf(grabbed);
  const QPoint drop = press + QPoint(12, -9);
  QSignalSpy status(&v.view, &ui::LinkageView::statusMessage);
  QTest::mouseMove(v.viewport(), press);
  REQUIRE(status.count() >= 1);
  CHECK(status.last().first().toString().contains("Drag E"));
  v.drag(press, drop, 6);
  const QPointF target = v.view.mapToScene(drop) - v.view.mapToScene(press) + grabbed;
  const k::Mechanism& original = before.mechanism;
  const auto expected =
      k::dragPoint(original, k::solvePose(original, {0.0, 0.0, 0.0}).value(), 0.0, e, toEigen(target));
  REQUIRE(expected);
  const auto& got = std::get<k::RrrPoint>(v.document.mechanism().points[e.index].definition);
  const auto& want = std::get<k::RrrPoint>(expected->mechanism.points[e.index].definition);
  CHECK(got.firstLength == Approx(want.firstLength).margin(1e-9));
  CHECK(got.secondLength == Approx(want.secondLength).margin(1e-9));
  CHECK(v.point(e).x() == Approx(target.x()).margin(1e-9));
  CHECK(v.point(e).y() == Approx(target.y()).margin(1e-9));
  CHECK(v.document.undoStack()->count() == 1);
  CHECK(v.document.undoStack()->undoText() == "Move E");
  v.document.undoStack()->undo();
  CHECK(v.document.design() == before);
}

TEST_CASE("a PRP pin has no handle, its two blocks sit on their guides", "[canvas][linkage]") {
  ShownView v(example("ls3-engine"));
  const auto request = k::suggestDyad(v.document.mechanism(), v.document.crankAngle(), k::DyadKind::Prp);
  const auto attached = k::attachToDesign(v.document.design(), request);
  REQUIRE(attached);
  REQUIRE_FALSE(v.document.edit(*attached, "attach").has_value());
  const k::PointId pin{v.document.mechanism().points.size() - 1};
  CHECK(v.scene().handleItem(pin) == nullptr);
  CHECK(v.scene().handles().size() == v.document.mechanism().points.size() - 1);
  std::size_t blocks = 0;
  for (const auto& s : v.scene().plan().sliders) blocks += s.joint == pin ? 1 : 0;
  CHECK(blocks == 2);
  CHECK(v.scene().sliderBlock(pin)->pos() == v.point(pin));
}
