// The synthesis panel (ui/synthesis/synthesis_panel.h): a crank-rocker problem fills the
// candidates table as the fields change; "Use this linkage" makes the candidate the document's
// design in one undo step, and the document's own analysis then finds the swing and time ratio
// asked for; a bad value is refused naming the field and changes nothing; a candidate with a
// defect is listed, marked, with its reason in the tooltip; the preview shows the chosen one
// only while the panel is shown.

#include "ui/synthesis/synthesis_panel.h"
#include "ui/synthesis/candidate_table.h"
#include "ui/synthesis/synthesis_forms.h"
#include "ui/synthesis/synthesis_preview_item.h"
#include "ui/synthesis/target_forms.h"
#include "ui/synthesis/target_table.h"

#include "ui/canvas/linkage_view.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/io/document_json.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/synthesis/swing_crank_rocker.h"

#include "tests/ui/canvas/canvas_test_support.h"
#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>

#include <cmath>

using namespace linkwright;
namespace k = kinematics;
using Problem = ui::SynthesisProblem;

namespace {

ui::CrankRockerForm& crankRockerForm(ui::SynthesisPanel& panel) {
  return *dynamic_cast<ui::CrankRockerForm*>(panel.form(Problem::Swing));
}

void ask(ui::SynthesisPanel& panel, double swingDeg, double timeRatio) {
  crankRockerForm(panel).swingBox()->setValue(swingDeg);
  crankRockerForm(panel).timeRatioBox()->setValue(timeRatio);
}

// Every cell of the table, to check that nothing reads nan or inf.
QStringList cellTexts(const QTableWidget& table) {
  QStringList out;
  for (int r = 0; r < table.rowCount(); ++r)
    for (int c = 0; c < table.columnCount(); ++c)
      if (const QTableWidgetItem* item = table.item(r, c)) out << item->text();
  return out;
}

}  // namespace

TEST_CASE("a crank-rocker for a 60° swing and time ratio 1.3 fills the candidates table", "[ui][synthesis]") {
  ui::MechanismDocument doc;
  doc.reset(testing::fourBar());
  ui::SynthesisPanel panel(&doc, nullptr);
  REQUIRE(panel.problem() == Problem::Swing);
  crankRockerForm(panel).countBox()->setValue(20);
  ask(panel, 60.0, 1.3);
  CHECK(panel.refusalMessage().isEmpty());
  REQUIRE(panel.outcome().has_value());
  // The best one, then the family.
  CHECK(panel.outcome()->rows.size() == 21);
  CHECK(panel.candidates()->rowCount() == 21);
  CHECK(panel.candidates()->item(0, ui::CandidateTable::Index)->text().endsWith("best"));
  CHECK(panel.candidates()->selectedRow() == std::optional<std::size_t>(0));
  // An exact construction: no error to show.
  CHECK(panel.candidates()->horizontalHeaderItem(ui::CandidateTable::Error)->text() == "Error");
  CHECK(panel.candidates()->item(0, ui::CandidateTable::Error)->text() == "exact");
  CHECK(panel.candidates()->item(0, ui::CandidateTable::Grashof)->text() == "crank-rocker");
  for (const QString& text : cellTexts(*panel.candidates())) {
    CAPTURE(text.toStdString());
    CHECK_FALSE(text.contains("nan", Qt::CaseInsensitive));
    CHECK_FALSE(text.contains("inf", Qt::CaseInsensitive));
  }
  // The table shows what the core gives for the same request.
  k::SwingTarget target{k::degToRad(60.0), 1.3, 45.0, k::SwingScale::Rocker, "mm"};
  const auto core = k::synthesiseCrankRocker(target, 20);
  REQUIRE(core.ok());
  CHECK(panel.outcome()->rows[0].candidate == core->best.candidate);
  CHECK(panel.candidates()->item(0, ui::CandidateTable::Transmission)->text() ==
        QString::number(k::radToDeg(core->best.candidate.minTransmission), 'f', 1));
  // Editing a field solves again at once.
  crankRockerForm(panel).countBox()->setValue(5);
  CHECK(panel.candidates()->rowCount() == 6);
}

TEST_CASE("using a candidate is one undo step, and the document's analysis gives the swing and ratio asked for",
          "[ui][synthesis]") {
  ui::MechanismDocument doc;
  k::Design start = testing::fourBar();
  start.omega = k::rpmToRadPerSec(10.0);  // kept when the linkage is replaced
  start.alpha = 0.5;
  doc.reset(start);
  const k::Design before = doc.design();
  ui::SynthesisPanel panel(&doc, nullptr);
  ask(panel, 59.0, 1.3);
  ask(panel, 60.0, 1.3);  // typed: one undo step, the targets' own
  REQUIRE(panel.outcome().has_value());
  const std::size_t row = GENERATE(0u, 3u, 10u);
  CAPTURE(row);
  panel.candidates()->selectRow(row);
  // The candidate, keeping the targets it was found for and the document's crank speed.
  k::Design chosen = panel.outcome()->rows[row].candidate.design;
  chosen.synthesis = panel.targets();
  chosen.omega = before.omega;
  chosen.alpha = before.alpha;
  const k::Design asked = doc.design();
  const int steps = doc.undoStack()->count();
  REQUIRE(panel.useButton()->isEnabled());
  QTest::mouseClick(panel.useButton(), Qt::LeftButton);
  CHECK(panel.refusalMessage().isEmpty());
  CHECK(doc.design() == chosen);
  CHECK(doc.undoStack()->count() == steps + 1);
  // Analysed by the document with the ordinary limit-position solver, not by the synthesis.
  const k::LimitReport& limits = doc.analysis().limits;
  REQUIRE(limits.rockerSwing.has_value());
  REQUIRE(limits.timeRatio.has_value());
  CHECK(*limits.rockerSwing == Approx(k::degToRad(60.0)).margin(1e-9));
  CHECK(*limits.timeRatio == Approx(1.3).margin(1e-9));

  doc.undoStack()->undo();
  CHECK(doc.design() == asked);
  // Typing the targets was one step of its own: the linkage itself never changed.
  doc.undoStack()->undo();
  CHECK(doc.design() == before);
  doc.undoStack()->redo();
  doc.undoStack()->redo();
  CHECK(doc.design() == chosen);
}

TEST_CASE("a bad time ratio or swing is refused naming the field, and nothing changes", "[ui][synthesis]") {
  ui::MechanismDocument doc;
  doc.reset(testing::fourBar());
  const k::Design before = doc.design();
  ui::SynthesisPanel panel(&doc, nullptr);
  ask(panel, 61.0, 1.3);
  REQUIRE(panel.outcome().has_value());
  const ui::SynthesisOutcome good = *panel.outcome();
  const int rows = panel.candidates()->rowCount();
  const k::Design accepted = doc.design();  // the targets accepted so far
  REQUIRE(accepted.synthesis.has_value());
  CHECK(accepted.synthesis->swing.timeRatio == 1.3);
  CHECK(accepted.mechanism == before.mechanism);
  const int steps = doc.undoStack()->count();

  SECTION("time ratio 0.5") {
    crankRockerForm(panel).timeRatioBox()->setValue(0.5);
    const QString why = panel.refusalMessage();
    CAPTURE(why.toStdString());
    CHECK(why.contains("Time ratio Q"));
    CHECK(why.contains("0.5"));
    CHECK(why.contains("between 1 and 100"));
  }
  SECTION("time ratio stepped down from 1.3 by the arrow key") {
    // Qt adds the step unrounded (1.3 - 1 = 0.30000000000000004); the box lands on what it shows,
    // and the refusal quotes that, in the form's words for the field (issue 57 item 10).
    QDoubleSpinBox* box = crankRockerForm(panel).timeRatioBox();
    box->setSingleStep(1.0);
    box->stepBy(-1);
    CHECK(box->value() == 0.3);
    const QString why = panel.refusalMessage();
    CAPTURE(why.toStdString());
    CHECK(why.contains("Time ratio Q must be"));
    CHECK(why.contains("(got 0.3)"));
    CHECK_FALSE(why.contains("timeRatio"));
  }
  SECTION("swing 190°") {
    crankRockerForm(panel).swingBox()->setValue(190.0);
    const QString why = panel.refusalMessage();
    CAPTURE(why.toStdString());
    CHECK(why.contains("Rocker swing"));
    CHECK(why.contains("190"));
    CHECK(why.contains("180°"));
  }
  CHECK(panel.outcome()->rows == good.rows);
  CHECK(panel.candidates()->rowCount() == rows);
  CHECK(doc.design() == accepted);
  CHECK(doc.undoStack()->count() == steps);
  // A good value again clears the refusal.
  ask(panel, 60.0, 1.3);
  CHECK(panel.refusalMessage().isEmpty());
}

TEST_CASE("a function generator outside its function's domain is refused naming the field", "[ui][synthesis]") {
  ui::MechanismDocument doc;
  ui::SynthesisPanel panel(&doc, nullptr);
  panel.setProblem(Problem::Function);
  REQUIRE(panel.refusalMessage().isEmpty());
  REQUIRE(panel.outcome().has_value());
  CHECK(panel.candidates()->horizontalHeaderItem(ui::CandidateTable::Error)->text() == "Error (°)");
  panel.form(Problem::Function)->numberBox("x0")->setValue(-1.0);  // log10 of a negative x
  CHECK(panel.refusalMessage().contains("x0"));
  CHECK(panel.refusalMessage().contains("x > 0"));
}

TEST_CASE("a candidate with a defect is listed, marked, with the reason in its tooltip", "[ui][synthesis]") {
  ui::MechanismDocument doc;
  ui::SynthesisPanel panel(&doc, nullptr);
  ask(panel, 60.0, 1.3);
  // No crank-rocker for this swing keeps μ above 89°: every candidate has that defect.
  panel.transmissionBoundBox()->setValue(89.0);
  REQUIRE(panel.outcome().has_value());
  const auto& rows = panel.outcome()->rows;
  REQUIRE(rows.size() == 42);
  CHECK(panel.candidates()->rowCount() == 42);
  const k::SynthesisCandidate& best = rows[0].candidate;
  REQUIRE(best.has(k::DefectKind::Transmission));
  CHECK(panel.candidates()->isMarked(0));
  CHECK(panel.candidates()->item(0, ui::CandidateTable::Index)->text().startsWith("⚠"));
  CHECK(panel.candidates()->item(0, ui::CandidateTable::Defects)->text().contains("transmission"));
  const QString tip = panel.candidates()->item(0, ui::CandidateTable::Defects)->toolTip();
  for (const k::Defect& d : best.defects) CHECK(tip.contains(QString::fromStdString(d.message)));

  // The best one keeps μ above 36° (36.04°): with a 30° bound it is clean, and shown so.
  panel.transmissionBoundBox()->setValue(30.0);
  REQUIRE(panel.outcome()->rows[0].candidate.defects.empty());
  CHECK_FALSE(panel.candidates()->isMarked(0));
}

TEST_CASE("the preview draws the chosen candidate while the panel is shown", "[ui][synthesis]") {
  ui::MechanismDocument doc;
  ui::LinkageView view(&doc);
  ui::SynthesisPanel panel(&doc, &view);
  ui::SynthesisPreviewItem* preview = panel.preview();
  CHECK(preview->scene() == view.linkageScene());
  CHECK_FALSE(preview->isVisible());
  panel.show();
  ask(panel, 60.0, 1.3);
  REQUIRE(panel.candidates()->selectedRow().has_value());
  CHECK(preview->isVisible());
  CHECK(preview->links().size() == 3);           // crank, coupler, rocker
  CHECK(preview->pivots().size() == 2);          // O2, O4
  CHECK(preview->targets().points.size() == 2);  // the rocker's two limit positions
  // Its bounds hold all it draws (the view repaints and culls by them).
  const QRectF bounds = preview->boundingRect();
  for (const QLineF& link : preview->links()) {
    CHECK(bounds.contains(link.p1()));
    CHECK(bounds.contains(link.p2()));
  }
  for (const Eigen::Vector2d& p : preview->targets().points) CHECK(bounds.contains(QPointF(p.x(), p.y())));
  // Drawn at the folded limit position: the crank's tip where the core's pose solver puts it.
  const auto& row = panel.outcome()->rows[0];
  const auto pose = k::solvePose(row.candidate.design.mechanism, {row.previewInput, 0.0, 0.0});
  REQUIRE(pose.ok());
  CHECK(preview->links()[0].p2() ==
        QPointF(pose->position[k::fourbar::kB.index].x(), pose->position[k::fourbar::kB.index].y()));
  panel.candidates()->clearSelection();
  CHECK_FALSE(preview->isVisible());
  panel.candidates()->selectRow(1);
  CHECK(preview->isVisible());
  // Used, the candidate is the document's linkage: no preview left drawn over it.
  QTest::mouseClick(panel.useButton(), Qt::LeftButton);
  REQUIRE(panel.refusalMessage().isEmpty());
  CHECK_FALSE(preview->isVisible());
  panel.candidates()->selectRow(2);
  CHECK(preview->isVisible());
  panel.hide();
  CHECK_FALSE(preview->isVisible());
}

TEST_CASE("a candidate off screen brings the view to it, one in view leaves the zoom alone", "[ui][synthesis]") {
  ui::test::ShownView shown;
  ui::SynthesisPanel panel(&shown.document, &shown.view);
  shown.view.zoomBy(40.0);  // the user looks closely at one joint of the thesis four-bar
  const QRectF before = shown.view.visibleRegion();
  panel.show();  // the tab opens on the default crank-rocker problem, solved at once
  ui::SynthesisPreviewItem* preview = panel.preview();
  REQUIRE(preview->isVisible());
  const QRectF candidate = preview->sceneBoundingRect();
  CHECK_FALSE(before.contains(candidate));
  CHECK(shown.view.visibleRegion().contains(candidate));
  // Zoomed out by the user, the next candidate is in view already: nothing moves under them.
  shown.view.zoomBy(0.25);
  const QTransform chosen = shown.view.viewportTransform();
  panel.candidates()->selectRow(1);
  REQUIRE(shown.view.visibleRegion().contains(preview->sceneBoundingRect()));
  CHECK(shown.view.viewportTransform() == chosen);
}

TEST_CASE("targets are kept in the document: typed ones as one undo step, saved ones shown again",
          "[ui][synthesis][file]") {
  ui::MechanismDocument doc;
  doc.reset(testing::fourBar());
  ui::SynthesisPanel panel(&doc, nullptr);
  CHECK_FALSE(doc.design().synthesis.has_value());  // opening the panel is not an edit
  CHECK(doc.undoStack()->count() == 0);
  ask(panel, 50.0, 1.25);
  crankRockerForm(panel).lengthBox()->setValue(30.0);
  REQUIRE(doc.design().synthesis.has_value());
  const k::SwingTarget swing = doc.design().synthesis->swing;
  CHECK(swing.swing == Approx(k::degToRad(50.0)).margin(1e-15));
  CHECK(swing.timeRatio == 1.25);
  CHECK(swing.length == 30.0);
  CHECK(doc.undoStack()->count() == 1);  // three fields typed, one step

  // A document that keeps targets shows them, on the problem it was saved with.
  k::Design saved = testing::fourBar();
  saved.synthesis = k::SynthesisTargets{};
  saved.synthesis->problem = Problem::Function;
  saved.synthesis->function = {
      "sqrt", 1.0, 4.0, k::degToRad(30.0), k::degToRad(90.0), k::degToRad(60.0), k::degToRad(75.0), 80.0, {}, 3};
  doc.reset(saved);
  CHECK(panel.problem() == Problem::Function);
  CHECK(panel.targets().function == saved.synthesis->function);
  CHECK(panel.targets().swing == saved.synthesis->swing);
  CHECK(doc.undoStack()->count() == 0);
  CHECK(doc.design() == saved);
  auto* function = dynamic_cast<ui::FunctionForm*>(panel.form(Problem::Function));
  REQUIRE(function != nullptr);
  CHECK(function->functionBox()->currentText() == QStringLiteral("√x"));
  CHECK(panel.outcome().has_value());  // solved from them

  // Undoing a typed target shows the one before.
  function->numberBox("x1")->setValue(9.0);
  CHECK(doc.design().synthesis->function.x1 == 9.0);
  doc.undoStack()->undo();
  CHECK(function->numberBox("x1")->value() == 4.0);
  CHECK(doc.design() == saved);
}

TEST_CASE("a target beyond the fields' range is refused in the designer, so what it keeps a document reads back",
          "[ui][synthesis][file][errors]") {
  ui::MechanismDocument doc;
  doc.reset(testing::fourBar());
  ui::SynthesisPanel panel(&doc, nullptr);
  panel.setProblem(Problem::Motion);
  auto* motion = dynamic_cast<ui::MotionForm*>(panel.form(Problem::Motion));
  REQUIRE(motion != nullptr);
  // A table cell took any finite number, and the document kept it: a pose at y = 1e300 that the
  // document reader, which holds targets to the fields' range, would refuse.
  motion->poses()->table()->item(1, 1)->setText(QStringLiteral("1e300"));
  const auto poses = motion->poses()->values();
  REQUIRE_FALSE(poses.ok());
  CHECK(poses.error().message == "Pose 2, y: must be within ±1e9 (got 1e300)");
  // The number fields' ends are the document's too.
  crankRockerForm(panel).swingBox()->setValue(-1e9);
  crankRockerForm(panel).lengthBox()->setValue(1e9);
  REQUIRE(doc.design().synthesis.has_value());
  for (const k::CouplerPose& pose : doc.design().synthesis->motion.poses) CHECK(std::abs(pose.point.y()) <= 1e9);
  const auto back = k::io::readDocument(k::io::writeDocument(doc.design()));
  INFO((back.ok() ? std::string() : back.error().message));
  REQUIRE(back.ok());
  CHECK(back->synthesis == doc.design().synthesis);
}
