// MechanismDocument: edits are validated and undoable, drags merge into one step, files
// round-trip, and a corrupt or newer file is refused without touching the open document.

#include "ui/document/document_file.h"
#include "ui/document/edit_design_command.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/design/design.h"
#include "kinematics/design/redrive.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/motion_law.h"

#include "tests/ui/support/four_bar_design.h"
#include "tests/ui/support/timed_design.h"

#include "tests/support/catch.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>

using namespace linkwright;
using ui::MechanismDocument;

namespace {

kinematics::Design withCrank(double crank) { return testing::fourBar({60.0, crank, 70.0, 45.0}); }

void writeText(const QString& path, const QByteArray& text) {
  QFile f(path);
  REQUIRE(f.open(QIODevice::WriteOnly));
  f.write(text);
}

}  // namespace

TEST_CASE("an edit changes the design, the analysis and the sweep, undo restores them exactly", "[ui][document]") {
  MechanismDocument doc;
  const kinematics::Design before = doc.design();
  QSignalSpy spy(&doc, &MechanismDocument::changed);
  const kinematics::Design after =
      testing::withLengths(before, {20.0, 25.0, 70.0, 45.0});  // 20 + 70 > 25 + 45: no longer Grashof
  REQUIRE_FALSE(doc.edit(after, "frame").has_value());
  CHECK(doc.design() == after);
  CHECK(doc.analysis().grashof->category == kinematics::GrashofClass::TripleRocker);
  CHECK_FALSE(doc.analysis().inputRange.fullRotation);
  CHECK(doc.pose().position[kinematics::fourbar::kO4.index].x() == 20.0);
  CHECK(spy.count() >= 1);
  doc.undoStack()->undo();
  CHECK(doc.design() == before);
  CHECK(doc.analysis().grashof->category == kinematics::GrashofClass::CrankRocker);
  doc.undoStack()->redo();
  CHECK(doc.design() == after);
}

TEST_CASE("an edit sweeps each grid once", "[ui][document]") {
  // A linkage's edit needs its design grid (validation, then the analysis) and the display
  // grid; the validation's sweep serves the analysis. A fully rotating four-bar has a closed
  // form for both, so only the display is swept.
  MechanismDocument doc;
  doc.reset(*kinematics::designForExample("watt-ii"));
  auto linkage = doc.design();
  std::get<kinematics::RrrPoint>(linkage.mechanism.points.back().definition).firstLength += 1.0;
  long before = doc.sweepsRun();
  REQUIRE_FALSE(doc.edit(linkage, "length").has_value());
  CHECK(doc.sweepsRun() - before == 2);
  before = doc.sweepsRun();
  doc.undoStack()->undo();  // nothing validated it: its grid is swept again, once
  CHECK(doc.sweepsRun() - before == 2);

  doc.reset(testing::fourBar());
  before = doc.sweepsRun();
  REQUIRE_FALSE(doc.edit(withCrank(20.0), "crank").has_value());
  CHECK(doc.sweepsRun() - before == 1);
}

TEST_CASE("an edit that can never be assembled is refused and changes nothing", "[ui][document][errors]") {
  MechanismDocument doc;
  const kinematics::Design before = doc.design();
  // coupler + rocker + crank cannot span the frame
  const kinematics::Design bad = testing::withLengths(before, {500.0, 25.0, 70.0, 45.0});
  const auto why = doc.edit(bad, "frame");
  REQUIRE(why.has_value());
  CHECK(why->contains("cannot be assembled at any crank angle"));
  CHECK(doc.design() == before);
  CHECK(doc.undoStack()->count() == 0);
  const kinematics::Design negative = testing::withLengths(before, {60.0, 25.0, -3.0, 45.0});
  const auto whyNegative = doc.edit(negative, "coupler");
  REQUIRE(whyNegative.has_value());
  CHECK(whyNegative->contains("coupler length must be positive and finite (got -3)"));
}

TEST_CASE("an edit outside the input domain is refused with the field, value and range", "[ui][document][errors]") {
  // The GUI's fields go through the core's checks: the same ranges as documents and the CLI.
  MechanismDocument doc;
  const kinematics::Design before = doc.design();
  const kinematics::Design huge = testing::withLengths(before, {60.0, 25.0, 70.0, 2e9});
  const auto whyHuge = doc.edit(huge, "rocker");
  REQUIRE(whyHuge.has_value());
  INFO(whyHuge->toStdString());
  CHECK(whyHuge->contains("rocker length must be between 1e-6 and 1e9 (got 2e+09)"));
  // 70 mm coupler: 7e6 times the crank
  const kinematics::Design spread = testing::withLengths(before, {60.0, 1e-5, 70.0, 45.0});
  const auto whySpread = doc.edit(spread, "crank");
  REQUIRE(whySpread.has_value());
  CHECK(whySpread->contains("lengths span too wide a range"));
  kinematics::Design fast = before;
  fast.omega = 2e6;
  const auto whyFast = doc.edit(fast, "speed");
  REQUIRE(whyFast.has_value());
  INFO(whyFast->toStdString());
  CHECK(whyFast->contains("omega must be finite and within ±1e6 rad/s (got 2e+06)"));
  CHECK(doc.design() == before);
  CHECK(doc.undoStack()->count() == 0);
}

TEST_CASE("consecutive edits with one merge key are one undo step", "[ui][document]") {
  MechanismDocument doc;
  const kinematics::Design start = doc.design();
  for (double crank = 24.0; crank > 20.0; crank -= 0.5) {
    const kinematics::Design d = testing::withLengths(doc.design(), {60.0, crank, 70.0, 45.0});
    REQUIRE_FALSE(
        doc.edit(d, "drag", ui::MergeKey{ui::ContinuousEdit::DragPoint, kinematics::fourbar::kB.index}).has_value());
  }
  CHECK(doc.undoStack()->count() == 1);
  doc.undoStack()->undo();
  CHECK(doc.design() == start);
}

TEST_CASE("the crank angle is kept inside the assemblable range", "[ui][document]") {
  MechanismDocument doc;
  const kinematics::Design d = testing::withLengths(doc.design(), {40, 30, 20, 25});  // non-Grashof: |θ2| ≤ 78.58°
  REQUIRE_FALSE(doc.edit(d, "lengths").has_value());
  doc.setCrankAngle(kinematics::degToRad(120.0));
  CHECK(kinematics::radToDeg(doc.crankAngle()) == Approx(78.5848).margin(1e-3));
  CHECK(doc.poseStatus() != kinematics::PoseStatus::NotAssemblable);
}

TEST_CASE("the request decides what the sweep computes", "[ui][document]") {
  MechanismDocument doc;
  doc.setRequest({false, false});
  CHECK(doc.sweep().linkOmega.empty());
  CHECK(doc.sweep().linkAlpha.empty());
  doc.setRequest({true, false});
  CHECK_FALSE(doc.sweep().linkOmega.empty());
  CHECK(doc.sweep().linkAlpha.empty());
}

TEST_CASE("save then open reproduces the document", "[ui][document][file]") {
  QTemporaryDir dir;
  const QString path = dir.filePath("linkage.json");
  kinematics::Design d = testing::fourBar({60.0, 22.5, 70.0, 45.0});
  d.mechanism = kinematics::withCouplerPoint(d.mechanism, *kinematics::asFourBar(d.mechanism),
                                             kinematics::CouplerPointSpec{30.0, 12.5})
                    .value();
  d.omega = 3.3;
  REQUIRE_FALSE(ui::saveDesignFile(path, d).has_value());
  kinematics::Design back;
  REQUIRE_FALSE(ui::loadDesignFile(path, back).has_value());
  CHECK(back == d);
}

TEST_CASE("documents are saved as .linkwright and opened from .linkwright or .json", "[ui][document][file]") {
  CHECK(ui::withDocumentSuffix("/tmp/arm") == "/tmp/arm.linkwright");
  CHECK(ui::withDocumentSuffix("/tmp/arm.json") == "/tmp/arm.json");
  CHECK(ui::withDocumentSuffix("/tmp/v1.2/arm") == "/tmp/v1.2/arm.linkwright");
  // A dot in the name is not an extension (issue 57: "0.0001" was saved without one).
  CHECK(ui::withDocumentSuffix("/tmp/0.0001") == "/tmp/0.0001.linkwright");
  CHECK(ui::withDocumentSuffix("/tmp/arm v1.2") == "/tmp/arm v1.2.linkwright");
  CHECK(ui::withDocumentSuffix("/tmp/arm.LINKWRIGHT") == "/tmp/arm.LINKWRIGHT");
  CHECK(ui::withDocumentSuffix("/tmp/arm.Json") == "/tmp/arm.Json");
  CHECK(ui::saveDocumentFilter().startsWith("Linkwright documents (*.linkwright)"));
  CHECK(ui::openDocumentFilter().contains("*.linkwright *.json"));
  // The content is the same JSON whatever the extension.
  QTemporaryDir dir;
  const QString path = dir.filePath("linkage.linkwright");
  REQUIRE_FALSE(ui::saveDesignFile(path, withCrank(24.0)).has_value());
  kinematics::Design back;
  REQUIRE_FALSE(ui::loadDesignFile(path, back).has_value());
  CHECK(back == withCrank(24.0));
}

TEST_CASE("missing, corrupt and newer files are refused with the reason", "[ui][document][file][errors]") {
  QTemporaryDir dir;
  const QString corrupt = dir.filePath("corrupt.json");
  writeText(corrupt, "{\"format\": \"linkwright\", \"version\": 1, \"mechanism\": ");
  const QString newer = dir.filePath("newer.json");
  writeText(newer, "{\"format\": \"linkwright\", \"version\": 9}");
  const kinematics::Design untouched = withCrank(21.0);
  kinematics::Design d = untouched;
  const auto missing = ui::loadDesignFile(dir.filePath("nope.json"), d);
  REQUIRE(missing.has_value());
  CHECK(missing->contains("does not exist"));
  const auto bad = ui::loadDesignFile(corrupt, d);
  REQUIRE(bad.has_value());
  CHECK(bad->contains("corrupt.json"));
  CHECK(bad->contains("not valid JSON"));
  const auto future = ui::loadDesignFile(newer, d);
  REQUIRE(future.has_value());
  CHECK(future->contains("newer Linkwright"));
  CHECK(d == untouched);
}

TEST_CASE("a failed save leaves the existing file intact", "[ui][document][file][errors]") {
  QTemporaryDir dir;
  const QString path = dir.filePath("keep.json");
  REQUIRE_FALSE(ui::saveDesignFile(path, withCrank(20.0)).has_value());
  QFile original(path);
  REQUIRE(original.open(QIODevice::ReadOnly));
  const QByteArray bytes = original.readAll();
  original.close();
  // A directory where the file should go cannot be written over.
  const auto why = ui::saveDesignFile(dir.path(), withCrank(30.0));
  REQUIRE(why.has_value());
  QFile again(path);
  REQUIRE(again.open(QIODevice::ReadOnly));
  CHECK(again.readAll() == bytes);
}

TEST_CASE("an edit that moves the crank restores the crank angle on undo", "[ui][document]") {
  MechanismDocument doc;
  doc.setCrankAngle(0.5);
  const kinematics::Design d = testing::withLengths(doc.design(), {60.0, 22.0, 70.0, 45.0});
  REQUIRE_FALSE(doc.edit(d, "move B", ui::MergeKey{ui::ContinuousEdit::DragPoint, kinematics::fourbar::kB.index}, 1.25)
                    .has_value());
  CHECK(doc.crankAngle() == 1.25);
  doc.undoStack()->undo();
  CHECK(doc.crankAngle() == 0.5);
  CHECK(doc.fourBar()->lengths.crank == 25.0);
  doc.undoStack()->redo();
  CHECK(doc.crankAngle() == 1.25);
}

TEST_CASE("a design whose crank follows a motion law opens and is swept on its time base", "[ui][document][law]") {
  MechanismDocument doc;
  const kinematics::Design timed = testing::cycloidalFourBar();
  CHECK_FALSE(doc.validate(timed).has_value());
  REQUIRE_FALSE(doc.edit(timed, "law").has_value());
  CHECK(doc.design() == timed);
  const kinematics::SweepResult& s = doc.sweep();
  REQUIRE(s.size() > 2);
  REQUIRE(s.time.size() == s.size());
  CHECK(s.time.front() == 0.0);
  CHECK(s.time.back() == testing::kRiseDuration);
  CHECK(s.inputAngle.back() == Approx(2.0 * kinematics::kPi).margin(1e-12));
  CHECK(doc.time() == 0.0);
  CHECK(doc.plotAxis() == ui::PlotAxis::Time);
}

TEST_CASE("on a time base the pose is the law's at the instant shown: its angle, ω and α", "[ui][document][law]") {
  MechanismDocument doc;
  doc.reset(testing::cycloidalFourBar());
  const double quarter = testing::kRiseDuration / 4.0;  // the cycloid's peak acceleration
  doc.setTime(quarter);
  CHECK(doc.time() == quarter);
  const auto& crank = kinematics::fourbar::kCrank;
  const double h = 2.0 * kinematics::kPi;
  const double T = testing::kRiseDuration;
  CHECK(doc.crankAngle() == Approx(h * (0.25 - 1.0 / (2.0 * kinematics::kPi))).margin(1e-12));
  CHECK(doc.pose().linkOmega[crank.index] == Approx(h / T).margin(1e-12));  // (h/T)(1 − cos π/2)
  CHECK(doc.pose().linkAlpha[crank.index] == Approx(2.0 * kinematics::kPi * h / (T * T)).margin(1e-9));
  // Times outside the time base are clamped into it.
  doc.setTime(7.0);
  CHECK(doc.time() == T);
  CHECK(doc.crankAngle() == Approx(h).margin(1e-12));
}

TEST_CASE("on a time base a crank angle is reached at the instant the law has it there", "[ui][document][law]") {
  MechanismDocument doc;
  doc.reset(testing::cycloidalFourBar());
  doc.setCrankAngle(kinematics::kPi);  // half the rise: at half the time, by symmetry
  CHECK(doc.time() == Approx(testing::kRiseDuration / 2.0).margin(1e-12));
  CHECK(doc.crankAngle() == Approx(kinematics::kPi).margin(1e-12));
}

TEST_CASE("undoing an edit on a time base restores the instant shown", "[ui][document][law]") {
  MechanismDocument doc;
  doc.reset(testing::cycloidalFourBar());
  doc.setTime(0.2);
  kinematics::Design slower = doc.design();
  slower.time->toTime = 0.1;  // the instant is clamped into the shorter time base
  REQUIRE_FALSE(doc.edit(slower, "to time").has_value());
  CHECK(doc.time() == 0.1);
  doc.undoStack()->undo();
  CHECK(doc.design() == testing::cycloidalFourBar());
  CHECK(doc.time() == 0.2);
}

TEST_CASE("a document file with a motion law round-trips and opens as it was saved", "[ui][document][law]") {
  QTemporaryDir dir;
  const QString path = dir.filePath("cycloid.linkwright");
  REQUIRE_FALSE(ui::saveDesignFile(path, testing::cycloidalFourBar()).has_value());
  kinematics::Design read;
  REQUIRE_FALSE(ui::loadDesignFile(path, read).has_value());
  CHECK(read == testing::cycloidalFourBar());
  MechanismDocument doc;
  CHECK_FALSE(doc.validate(read).has_value());
}

TEST_CASE("a linear input on a time base is reached where the law has it, not a turn's length away",
          "[ui][document][law]") {
  MechanismDocument doc;
  doc.reset(kinematics::designForExample("piston-driven").value());
  doc.setTime(0.04);  // near the end of the rise, about 70 mm along
  // 2π mm past the start is one position among many, not the start again.
  const double q = 1.0 + 2.0 * kinematics::kPi;
  doc.setCrankAngle(q);
  CHECK(doc.crankAngle() == Approx(q).margin(1e-9));
  CHECK(kinematics::motionAt(doc.design().time->law, doc.time()).position == Approx(q).margin(1e-9));
}

TEST_CASE("a design on a linear grid opens at its grid's start, inside the range", "[ui][document]") {
  const kinematics::Design ls3 = kinematics::designForExample("ls3-engine").value();
  const auto piston = kinematics::driveFrom(ls3, ls3.mechanism.findPoint("C").value(), 1.0);
  REQUIRE(piston.ok());
  MechanismDocument doc;
  doc.reset(piston->design);
  CHECK(doc.crankAngle() == Approx(piston->design.fromDeg).margin(1e-12));
}
