#pragma once
// A document with a LinkageView shown offscreen at a fixed size, and helpers to find the
// drawn points and to press, move and release the mouse on the view.

#include "ui/canvas/linkage_scene.h"
#include "ui/canvas/linkage_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/geometry.h"

#include "kinematics/design/design.h"
#include "kinematics/model/fourbar.h"
#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <QApplication>
#include <QTest>
#include <QWheelEvent>

namespace linkwright::ui::test {

inline kinematics::Design nonGrashofDesign() { return linkwright::testing::fourBar({40.0, 30.0, 20.0, 25.0}); }

struct ShownView {
  MechanismDocument document;
  LinkageView view{&document};

  explicit ShownView(const std::optional<kinematics::Design>& design = std::nullopt) {
    if (design) document.reset(*design);
    view.resize(800, 600);
    view.show();
    REQUIRE(QTest::qWaitForWindowExposed(&view));
  }

  QWidget* viewport() { return view.viewport(); }
  LinkageScene& scene() { return *dynamic_cast<LinkageScene*>(view.linkageScene()); }
  /// A point of the document's current pose, in scene coordinates.
  QPointF point(kinematics::PointId id) const { return toQt(document.pose().position[id.index]); }
  QPoint pixelOf(const QPointF& scenePoint) const { return view.mapFromScene(scenePoint); }

  /// Press at `from`, move there in `steps` steps, release at `to` (viewport pixels).
  void drag(const QPoint& from, const QPoint& to, int steps = 10) {
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, from);
    for (int i = 1; i <= steps; ++i) QTest::mouseMove(viewport(), from + (to - from) * i / steps);
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, to);
  }

  /// Turns the wheel by `notches` (positive: zoom in) with the pointer at `at`.
  void wheel(const QPoint& at, int notches) {
    QWheelEvent event(QPointF(at), QPointF(viewport()->mapToGlobal(at)), QPoint(), QPoint(0, 120 * notches),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &event);
  }
};

}  // namespace linkwright::ui::test
