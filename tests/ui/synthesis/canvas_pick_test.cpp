// Targets picked on the canvas (LinkageView's pick mode, driven by the synthesis panel's
// "Pick on canvas" toggles): a click appends the clicked model point to the path's targets, a
// press-drag-release appends a pose with the dragged direction, and with the toggle off a
// click does what it always did.

#include "ui/synthesis/synthesis_panel.h"
#include "ui/synthesis/target_forms.h"
#include "ui/synthesis/target_table.h"

#include "tests/ui/canvas/canvas_test_support.h"

#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <QPushButton>
#include <QTableWidget>

#include <cmath>

using namespace linkwright;
namespace k = kinematics;
using Problem = ui::SynthesisProblem;
using linkwright::ui::test::ShownView;

namespace {

double cellValue(const ui::TargetTable& table, int row, int column) {
  return table.table()->item(row, column)->text().toDouble();
}

}  // namespace

TEST_CASE("a click on the canvas appends the clicked model point to the path's targets", "[ui][synthesis][pick]") {
  ShownView v;
  ui::SynthesisPanel panel(&v.document, &v.view);
  panel.setProblem(Problem::Path);
  ui::TargetTable& points = *panel.pathForm()->points();
  const int rows = points.rowCount();
  points.pickButton()->click();
  CHECK(v.view.pickMode() == ui::LinkageView::PickMode::Point);

  const QPointF model(12.5, -7.25);
  const QPoint pixel = v.pixelOf(model);
  QTest::mouseClick(v.viewport(), Qt::LeftButton, Qt::NoModifier, pixel);
  REQUIRE(points.rowCount() == rows + 1);
  // The pixel the point maps to, back in the model: within one pixel of the point (table cells
  // keep six significant digits).
  const QPointF clicked = v.view.mapToScene(pixel);
  const double pixelSize = 1.0 / v.view.pixelsPerUnit();
  CHECK(cellValue(points, rows, 0) == Approx(clicked.x()).margin(1e-4));
  CHECK(cellValue(points, rows, 1) == Approx(clicked.y()).margin(1e-4));
  CHECK(std::abs(cellValue(points, rows, 0) - model.x()) < pixelSize);
  CHECK(std::abs(cellValue(points, rows, 1) - model.y()) < pixelSize);
  // The document keeps the new target (one undo step); its linkage is as it was.
  CHECK(v.document.undoStack()->count() == 1);
  REQUIRE(v.document.design().synthesis.has_value());
  CHECK(v.document.design().synthesis->path.points.back() ==
        Eigen::Vector2d(cellValue(points, rows, 0), cellValue(points, rows, 1)));

  // Off again: a click no longer picks.
  points.pickButton()->click();
  CHECK(v.view.pickMode() == ui::LinkageView::PickMode::None);
  QTest::mouseClick(v.viewport(), Qt::LeftButton, Qt::NoModifier, pixel + QPoint(20, 0));
  CHECK(points.rowCount() == rows + 1);
}

TEST_CASE("a press, drag and release on the canvas appends a coupler pose", "[ui][synthesis][pick]") {
  ShownView v;
  ui::SynthesisPanel panel(&v.document, &v.view);
  panel.setProblem(Problem::Motion);
  auto* motion = dynamic_cast<ui::MotionForm*>(panel.form(Problem::Motion));
  REQUIRE(motion != nullptr);
  ui::TargetTable& poses = *motion->poses();
  poses.setRows({{0.0, 0.0, 0.0}, {40.0, 20.0, 25.0}});
  poses.pickButton()->click();
  CHECK(v.view.pickMode() == ui::LinkageView::PickMode::Pose);

  const QPoint press = v.pixelOf({30.0, 10.0});
  const QPoint release = press + QPoint(40, -40);  // up and to the right on screen: 45° in the model
  v.drag(press, release, 5);
  REQUIRE(poses.rowCount() == 3);
  const QPointF at = v.view.mapToScene(press);
  CHECK(cellValue(poses, 2, 0) == Approx(at.x()).margin(1e-4));
  CHECK(cellValue(poses, 2, 1) == Approx(at.y()).margin(1e-4));
  CHECK(cellValue(poses, 2, 2) == Approx(45.0).margin(1e-3));

  // The table is full: a further pick is refused, naming it, and changes nothing.
  v.drag(press, release, 2);
  CHECK(poses.rowCount() == 3);
  CHECK(panel.refusalMessage().contains("Poses"));

  // Switching problems ends picking.
  panel.setProblem(Problem::Swing);
  CHECK(v.view.pickMode() == ui::LinkageView::PickMode::None);
  CHECK_FALSE(poses.pickButton()->isChecked());
}
