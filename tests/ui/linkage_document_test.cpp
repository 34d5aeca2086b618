// Any linkage, not only four-bars, through the document: examples and File ▸ New templates
// solve and assemble, a point drag (dragPoint) is one undo step that undo reverts exactly, the
// dimensions panel edits through the same path, attaching a dyad adds links (or is refused
// with the core's reason, changing nothing), files round-trip, and the analysis shows what
// applies (mobility, quick return, unassembled ranges).

#include "ui/canvas/design_drag.h"
#include "ui/dialogs/attach_dyad_dialog.h"
#include "ui/document/design_templates.h"
#include "ui/document/document_file.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/analysis_panel.h"
#include "ui/panels/dimensions_panel.h"

#include "kinematics/design/dyad_request.h"
#include "kinematics/design/point_drag.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "tests/support/locking_six_bar.h"

#include "tests/support/catch.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QTemporaryDir>

using namespace linkwright;
namespace k = linkwright::kinematics;
using ui::MechanismDocument;

namespace {

k::Design example(const std::string& name) { return *k::designForExample(name); }

std::size_t assembledSamples(const k::SweepResult& s) {
  std::size_t n = 0;
  for (std::size_t j = 0; j < s.size(); ++j) n += s.assembled(j) ? 1 : 0;
  return n;
}

}  // namespace

TEST_CASE("every example and every New template opens, solves and assembles", "[ui][linkage]") {
  std::vector<std::pair<std::string, k::Design>> designs;
  for (const auto& t : ui::designTemplates()) designs.emplace_back(t.kind, ui::templateDesign(t));
  for (const auto& e : k::examples()) designs.emplace_back(e.name, example(e.name));
  MechanismDocument doc;
  for (const auto& [name, design] : designs) {
    CAPTURE(name);
    REQUIRE_FALSE(doc.validate(design).has_value());
    doc.reset(design);
    CHECK(doc.design() == design);
    CHECK(doc.poseStatus() != k::PoseStatus::NotAssemblable);
    CHECK(assembledSamples(doc.sweep()) > 0);
    CHECK(doc.analysis().mobility.mobility == 1);
    CHECK(doc.undoStack()->count() == 0);
  }
  // The kinds File ▸ New lists are the ones the brief names, in order, then the linkages
  // driven other than by a crank.
  QStringList labels;
  for (const auto& t : ui::designTemplates()) labels << QString(t.label).remove('&');
  CHECK(labels == QStringList{"Four-bar", "Slider-crank", "Crank-shaper", "Whitworth quick return", "Watt I six-bar",
                              "Watt II six-bar", "Stephenson I six-bar", "Stephenson III six-bar", "Two-link arm",
                              "Piston-driven slider-crank", "Cylinder-driven boom"});
}

TEST_CASE("a slider-crank and a Watt II solve through the document", "[ui][linkage]") {
  MechanismDocument doc;
  doc.reset(example("ls3-engine"));
  CHECK_FALSE(doc.fourBar().has_value());
  CHECK(doc.analysis().inputRange.fullRotation);
  CHECK_FALSE(doc.analysis().grashof.has_value());
  CHECK(doc.sweep().notAssembled.empty());
  // The piston at crank 0 is at crank + rod from O2 (the core says so; this only reads it).
  const k::Pose expected = k::solvePose(doc.mechanism(), {0.0, 0.0, 0.0}).value();
  CHECK(doc.pose().position[2] == expected.position[2]);
  doc.setCrankAngle(k::degToRad(90.0));
  CHECK(doc.crankAngle() == Approx(k::kPi / 2.0));

  doc.reset(example("watt-ii"));
  CHECK(doc.mechanism().points.size() == 7);
  CHECK(doc.mechanism().links.size() == 5);
  CHECK(doc.poseStatus() == k::PoseStatus::Ok);
}

TEST_CASE("a lock between two samples splits the range the crank can turn through", "[ui][linkage][analysis]") {
  // In 5° steps every sample assembles, but the linkage locks between 290° and 295°, so the
  // animator must not turn it through a full circle.
  k::Design d;
  d.kind = "stephenson-iii";
  d.mechanism = *k::makeSixBar(test::lockingSixBar());
  d.samples = 73;
  MechanismDocument doc;
  doc.reset(d);
  CHECK(doc.analysis().notAssembled.empty());  // the grid's samples all assemble
  const k::InputRange& range = doc.analysis().inputRange;
  CHECK_FALSE(range.fullRotation);
  REQUIRE(range.ranges.size() == 2);
  CHECK(k::radToDeg(range.ranges[0].from) == Approx(0.0));
  CHECK(k::radToDeg(range.ranges[0].to) == Approx(290.0));
  CHECK(k::radToDeg(range.ranges[1].from) == Approx(295.0));
  CHECK(k::radToDeg(range.ranges[1].to) == Approx(360.0));
}

TEST_CASE("a shaper shows its quick return, a Whitworth too", "[ui][linkage][analysis]") {
  MechanismDocument doc;
  ui::AnalysisPanel panel(&doc);
  doc.reset(example("shaper"));
  REQUIRE(doc.analysis().quickReturn.has_value());
  const auto q = k::shaperQuickReturn(k::kSeedShaper);
  REQUIRE(q.has_value());
  CHECK(doc.analysis().quickReturn == q);
  CHECK(panel.timeRatioText().startsWith(QString::number(q->timeRatio, 'f', 4)));
  CHECK(panel.strokeText().startsWith(QString::number(q->stroke, 'f', 2)));
  CHECK(panel.mobilityText().endsWith("= 1"));
  doc.reset(example("whitworth"));
  CHECK(doc.analysis().quickReturn == k::shaperQuickReturn(k::kWhitworth));
  doc.reset(example("watt-ii"));
  CHECK_FALSE(doc.analysis().quickReturn.has_value());
  CHECK(panel.timeRatioText().isEmpty());
}

TEST_CASE("a four-bar stored as a general linkage still shows its Grashof class and limits",
          "[ui][linkage][analysis]") {
  // What the panel shows depends on what the linkage is, not on how the design was stored.
  k::Design d;                                                               // kind "linkage"
  d.mechanism = *k::makeFourBar({20.0, 25.0, 70.0, 45.0}, k::Branch::Open);  // 20 + 70 > 25 + 45
  MechanismDocument doc;
  ui::AnalysisPanel panel(&doc);
  doc.reset(d);
  CHECK(doc.design().kind == "linkage");
  REQUIRE(doc.fourBar().has_value());
  REQUIRE(doc.analysis().grashof.has_value());
  CHECK(doc.analysis().grashof->category == k::GrashofClass::TripleRocker);
  CHECK(panel.grashofText().contains("Triple-rocker"));
  CHECK(doc.analysis().inputRange == k::fourBarInputRange({20.0, 25.0, 70.0, 45.0}));
}

TEST_CASE("a drag of any point goes through dragPoint, is one undo step, and undo restores it exactly",
          "[ui][linkage][drag]") {
  for (const std::string name : {"ls3-engine", "watt-ii", "shaper"}) {
    CAPTURE(name);
    MechanismDocument doc;
    doc.reset(example(name));
    const k::Design before = doc.design();
    const k::PointId last{doc.mechanism().points.size() - 1};
    const Eigen::Vector2d at = doc.pose().position[last.index];
    // Three moves of one drag, as the canvas makes them: one merge key.
    for (const double dy : {1.0, 2.0, 3.0}) {
      const auto dragged = ui::dragDesign(doc, last, at + Eigen::Vector2d(2.0, dy));
      REQUIRE(dragged);
      REQUIRE_FALSE(
          doc.edit(dragged->design, "drag", ui::MergeKey{ui::ContinuousEdit::DragPoint, last.index}).has_value());
    }
    CHECK(doc.design() != before);
    CHECK(doc.undoStack()->count() == 1);
    // The same as one dragPoint from where the drag started: the parents did not move.
    const k::Mechanism& original = before.mechanism;
    const auto expected = k::dragPoint(original, k::solvePose(original, {0.0, 0.0, 0.0}).value(), 0.0, last,
                                       at + Eigen::Vector2d(2.0, 3.0));
    REQUIRE(expected);
    CHECK(doc.mechanism() == expected->mechanism);
    doc.undoStack()->undo();
    CHECK(doc.design() == before);
  }
}

TEST_CASE("a drag that cannot be assembled at the shown crank angle is refused", "[ui][linkage][drag]") {
  MechanismDocument doc;
  doc.reset(example("watt-ii"));
  // O6 (point 5) far away: E cannot reach it from P.
  const auto dragged = ui::dragDesign(doc, k::PointId{5}, Eigen::Vector2d(1000.0, 0.0));
  REQUIRE_FALSE(dragged);
  CHECK(dragged.error().message.find("cannot be assembled") != std::string::npos);
}

TEST_CASE("the dimensions panel edits any linkage through the document", "[ui][linkage][panels]") {
  MechanismDocument doc;
  doc.reset(example("ls3-engine"));
  ui::DimensionsPanel panel(&doc);
  const auto& fields = panel.fields();
  REQUIRE_FALSE(fields.empty());
  // The rod: C's length to B.
  std::size_t rod = fields.size();
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (fields[i].parameter == k::Parameter{k::PointId{2}, k::ParameterSlot::Length}) rod = i;
  REQUIRE(rod < fields.size());
  CHECK(panel.editor(rod)->value() == Approx(6.098 * 25.4));
  panel.editor(rod)->setValue(160.0);
  const auto* c = std::get_if<k::RrpPoint>(&doc.mechanism().points[2].definition);
  REQUIRE(c != nullptr);
  CHECK(c->length == 160.0);
  CHECK(doc.undoStack()->count() == 1);
  // The guide moved 500 mm off: the rod cannot reach it at any crank angle. Refused, and the
  // editor snaps back.
  std::size_t guideY = fields.size();
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (fields[i].parameter == k::Parameter{k::PointId{2}, k::ParameterSlot::GuideY}) guideY = i;
  REQUIRE(guideY < fields.size());
  panel.editor(guideY)->setValue(500.0);
  CHECK(panel.refusalMessage().contains("cannot be assembled at any crank angle"));
  CHECK(std::get<k::RrpPoint>(doc.mechanism().points[2].definition).guide.point.y() == 0.0);
  CHECK(panel.editor(guideY)->value() == 0.0);
  CHECK(doc.undoStack()->count() == 1);
  doc.undoStack()->undo();
  CHECK(doc.design() == example("ls3-engine"));
  REQUIRE(panel.branchBox(k::PointId{2}) != nullptr);
  panel.branchBox(k::PointId{2})->setCurrentIndex(1);
  CHECK(std::get<k::RrpPoint>(doc.mechanism().points[2].definition).branch == k::Branch::Crossed);
}

TEST_CASE("attaching a dyad to a four-bar adds two links, undoably", "[ui][linkage][attach]") {
  MechanismDocument doc;  // the thesis crank-rocker
  const k::Design fourBar = doc.design();
  const k::DyadRequest request = k::suggestDyad(doc.mechanism(), doc.crankAngle(), k::DyadKind::Rrr);
  CHECK(request.joint == "E");
  const auto attached = k::attachToDesign(doc.design(), request);
  REQUIRE(attached);
  REQUIRE_FALSE(doc.edit(*attached, "attach").has_value());
  CHECK(doc.design().kind == "linkage");
  CHECK_FALSE(doc.fourBar().has_value());
  CHECK(doc.mechanism().links.size() == 5);
  CHECK(doc.mechanism().links[3].name == "link5");
  CHECK(doc.mechanism().findPoint("E").has_value());
  CHECK(doc.poseStatus() != k::PoseStatus::NotAssemblable);
  CHECK(doc.analysis().mobility.mobility == 1);
  doc.undoStack()->undo();
  CHECK(doc.design() == fourBar);
}

TEST_CASE("every kind of dyad attaches to a slider-crank from its suggestion", "[ui][linkage][attach]") {
  for (const auto kind : {k::DyadKind::Rrr, k::DyadKind::Rrp, k::DyadKind::Rpr, k::DyadKind::Prp}) {
    CAPTURE(static_cast<int>(kind));
    MechanismDocument doc;
    doc.reset(example("ls3-engine"));
    const std::size_t points = doc.mechanism().points.size();
    const k::DyadRequest request = k::suggestDyad(doc.mechanism(), doc.crankAngle(), kind);
    const auto attached = k::attachToDesign(doc.design(), request);
    REQUIRE(attached);
    const auto refusal = doc.edit(*attached, "attach");
    CAPTURE(refusal.value_or(QString()).toStdString());
    REQUIRE_FALSE(refusal.has_value());
    CHECK(doc.mechanism().points.size() > points);
    CHECK(k::solvePose(doc.mechanism(), {doc.crankAngle(), 0.0, 0.0}, {false, false}));
  }
}

TEST_CASE("the dialog attaches, or shows the core's refusal and changes nothing", "[ui][linkage][attach]") {
  MechanismDocument doc;
  doc.reset(example("shaper"));
  const k::Design before = doc.design();
  const auto apply = [&doc](const k::DyadRequest& r) -> std::optional<QString> {
    const auto attached = k::attachToDesign(doc.design(), r);
    if (!attached) return QString::fromStdString(attached.error().message);
    return doc.edit(*attached, "attach");
  };
  ui::AttachDyadDialog dialog(doc.mechanism(), doc.crankAngle(), apply);
  CHECK(dialog.grab().save(QStringLiteral("/tmp/linkwright_attach_dyad.png")));
  // A joint name already taken: refused by name, dialog open, document unchanged.
  k::DyadRequest bad = dialog.request();
  bad.joint = "B";
  dialog.setRequest(bad);
  dialog.accept();
  CHECK(dialog.errorText().contains("already a point named B"));
  CHECK(dialog.result() != QDialog::Accepted);
  CHECK(doc.design() == before);
  // RRR lengths that cannot close: the document refuses with the solver's sentence.
  k::DyadRequest tooShort = k::suggestDyad(doc.mechanism(), doc.crankAngle(), k::DyadKind::Rrr);
  tooShort.firstLength = tooShort.secondLength = 1e-3;
  dialog.setRequest(tooShort);
  dialog.accept();
  CHECK(dialog.errorText().contains("cannot be assembled"));
  CHECK(doc.design() == before);
  // The suggestion (a new ground pivot, lengths from the pose) is accepted.
  dialog.setRequest(k::suggestDyad(doc.mechanism(), doc.crankAngle(), k::DyadKind::Rrr));
  dialog.accept();
  CHECK(dialog.result() == QDialog::Accepted);
  CHECK(doc.mechanism().points.size() == 7);  // a new ground pivot and the joint
  CHECK(doc.undoStack()->count() == 1);
}

TEST_CASE("any linkage saves and opens unchanged", "[ui][linkage][file]") {
  QTemporaryDir dir;
  for (const std::string name : {"ls3-engine", "watt-ii", "shaper", "stephenson-i"}) {
    CAPTURE(name);
    const QString path = dir.filePath(QString::fromStdString(name) + ".json");
    const k::Design design = example(name);
    REQUIRE_FALSE(ui::saveDesignFile(path, design).has_value());
    k::Design back;
    REQUIRE_FALSE(ui::loadDesignFile(path, back).has_value());
    CHECK(back == design);
  }
}
