// The Polygons tab against the solver: what the view draws (its arrows, in the polygon plane)
// and what its table prints (each arrow's length read off the drawing, each image against the
// solver's velocity or acceleration of its point) must be the exact solution. Tolerance:
// 1e-9 of the polygon's size, as the core's polygon tests (the solver's rates are good to
// ~1e-15 relative; drawing to scale and reading back adds one division and one product).
#include "ui/classroom/polygon_panel.h"
#include "ui/classroom/polygon_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"

#include "kinematics/design/examples.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <QComboBox>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>

#include <algorithm>

using namespace linkwright;
using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

double sizeOf(const k::VectorPolygon& p) {
  double size = 0.0;
  for (const k::PolygonImage& im : p.images) size = std::max(size, im.position.norm());
  return std::max(size, 1e-300);
}

double cellValue(const QTableWidget* table, int row, int column) {
  return table->item(row, column)->data(Qt::UserRole).toDouble();
}

// The document's pose solved again, independently of the document, with every rate.
k::Pose solverPose(const MechanismDocument& doc) {
  const k::DriverState driver{doc.crankAngle(), doc.design().omega, doc.design().alpha};
  return k::solvePose(doc.mechanism(), driver).value();
}

void checkKind(PolygonPanel& panel, const MechanismDocument& doc, k::PolygonKind kind) {
  panel.setKind(kind);
  const k::Pose pose = solverPose(doc);
  const bool velocity = kind == k::PolygonKind::Velocity;
  const k::VectorPolygon exact =
      velocity ? k::velocityPolygon(doc.mechanism(), pose) : k::accelerationPolygon(doc.mechanism(), pose);
  const std::vector<Eigen::Vector2d>& rates = velocity ? pose.velocity : pose.acceleration;
  const double tol = 1e-9 * sizeOf(exact);
  const std::vector<k::PolygonVector> drawn = panel.view()->drawnVectors();
  REQUIRE(drawn.size() == exact.vectors.size());
  REQUIRE(!drawn.empty());
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    INFO(drawn[i].label);
    CHECK(drawn[i].label == exact.vectors[i].label);
    CHECK(drawn[i].step == exact.vectors[i].step);
    CHECK((drawn[i].from - exact.vectors[i].from).norm() <= tol);
    CHECK((drawn[i].to - exact.vectors[i].to).norm() <= tol);
    // A point's absolute arrow from the pole is the solver's velocity (acceleration) itself.
    if (drawn[i].term == k::VectorTerm::Absolute && drawn[i].from.norm() <= tol)
      CHECK((drawn[i].value() - rates[drawn[i].point.index]).norm() <= tol);
  }
  // The table: every arrow's read-off length is its exact magnitude; every image check reads
  // the solver's speed of the point.
  const QTableWidget* table = panel.table();
  REQUIRE(panel.arrowRows() == static_cast<int>(drawn.size()));
  const double scale = panel.view()->scale();
  for (int row = 0; row < panel.arrowRows(); ++row) {
    const double magnitude = exact.vectors[row].value().norm();
    CHECK(std::abs(cellValue(table, row, PolygonPanel::ReadOffColumn) - magnitude) <= tol);
    CHECK(std::abs(cellValue(table, row, PolygonPanel::ExactColumn) - magnitude) <= tol);
    CHECK(std::abs(cellValue(table, row, PolygonPanel::DrawnColumn) * scale - magnitude) <= tol);
  }
  int checks = 0;
  std::vector<k::PointId> subjects;  // an RPR dyad's block ends two equations: one row
  for (const k::PolygonEquation& e : exact.equations)
    if (std::find(subjects.begin(), subjects.end(), e.subject) == subjects.end()) subjects.push_back(e.subject);
  for (const k::PointId subject : subjects) {
    const double solver = rates[subject.index].norm();
    for (int row = panel.arrowRows(); row < table->rowCount(); ++row) {
      const QString vector = table->item(row, PolygonPanel::VectorColumn)->text();
      if (!vector.endsWith("o" + QString::fromStdString(doc.mechanism().points[subject.index].name).toLower()))
        continue;
      CHECK(std::abs(cellValue(table, row, PolygonPanel::ReadOffColumn) - solver) <= tol);
      CHECK(std::abs(cellValue(table, row, PolygonPanel::ExactColumn) - solver) <= tol);
      ++checks;
    }
  }
  CHECK(checks == table->rowCount() - panel.arrowRows());
  CHECK(checks > 0);
}

}  // namespace

TEST_CASE("the polygon view draws the solver's polygons and its table reads the solver's values", "[ui][classroom]") {
  const std::string name = GENERATE("thesis-crank-rocker", "alvi-fourbar", "ls3-engine", "shaper");
  const double deg = GENERATE(30.0, 100.0, 200.0, 290.0);
  INFO(name << " at " << deg << "°");
  MechanismDocument doc;
  doc.reset(*k::designForExample(name));
  PolygonPanel panel(&doc);
  panel.resize(600, 800);
  doc.setCrankAngle(k::degToRad(deg));
  REQUIRE(panel.polygons().has_value());
  CHECK(panel.reason().isEmpty());
  checkKind(panel, doc, k::PolygonKind::Velocity);
  checkKind(panel, doc, k::PolygonKind::Acceleration);
  // At a chosen round scale the drawing (cm) changes, the values read off it do not.
  panel.setChosenScale(panel.view()->fitScale() * 2.0);
  checkKind(panel, doc, k::PolygonKind::Acceleration);
}

TEST_CASE("Step draws the arrows one at a time in the order a student draws them", "[ui][classroom]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("shaper"));
  PolygonPanel panel(&doc);
  doc.setCrankAngle(k::degToRad(60.0));
  panel.setKind(k::PolygonKind::Acceleration);
  const std::vector<k::PolygonVector>& all = panel.polygons()->acceleration.vectors;
  REQUIRE(std::any_of(all.begin(), all.end(), [](const auto& v) { return v.term == k::VectorTerm::Coriolis; }));
  panel.findChild<QPushButton*>("PolygonReset")->click();
  CHECK(panel.view()->drawnVectors().empty());
  CHECK(panel.table()->rowCount() == 0);
  auto* stepButton = panel.findChild<QPushButton*>("PolygonStep");
  for (std::size_t n = 1; n <= all.size(); ++n) {
    stepButton->click();
    const std::vector<k::PolygonVector> drawn = panel.view()->drawnVectors();
    REQUIRE(drawn.size() == n);
    CHECK(drawn.back() == all[n - 1]);
    CHECK(panel.arrowRows() == static_cast<int>(n));
    if (n > 1) CHECK(drawn[n - 1].step > drawn[n - 2].step);
  }
  // The crank moves on: as many arrows stay drawn, now those of the new pose.
  doc.setCrankAngle(k::degToRad(61.0));
  panel.reset();
  stepButton->click();
  stepButton->click();
  CHECK(panel.view()->drawnVectors().size() == 2);
  doc.setCrankAngle(k::degToRad(62.0));
  CHECK(panel.view()->drawnVectors().size() == 2);
  CHECK(panel.view()->drawnVectors()[1] == panel.polygons()->acceleration.vectors[1]);
  panel.findChild<QPushButton*>("PolygonAll")->click();
  CHECK(panel.view()->drawnVectors().size() == all.size());
}

TEST_CASE("a chosen round scale stays while the crank turns, each polygon keeps its own", "[ui][classroom]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("thesis-crank-rocker"));
  PolygonPanel panel(&doc);
  auto* box = panel.findChild<QComboBox*>("PolygonScale");
  REQUIRE(box->itemData(box->currentIndex()).toDouble() == 0.0);  // fit
  CHECK(box->currentText().startsWith("Fit: 1 cm = "));
  const double chosen = panel.view()->fitScale() * 5.0;  // a round scale times 5 is one too
  panel.setChosenScale(chosen);
  for (const double deg : {10.0, 120.0, 250.0}) {
    doc.setCrankAngle(k::degToRad(deg));
    CHECK(panel.view()->scale() == chosen);
    CHECK(box->itemData(box->currentIndex()).toDouble() == chosen);
  }
  panel.setKind(k::PolygonKind::Acceleration);
  CHECK(panel.view()->chosenScale() == 0.0);
  panel.setKind(k::PolygonKind::Velocity);
  CHECK(panel.view()->chosenScale() == chosen);
}

TEST_CASE("a linkage not driven by a crank shows why there are no polygons", "[ui][classroom]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("excavator-boom"));
  PolygonPanel panel(&doc);
  CHECK_FALSE(panel.polygons().has_value());
  CHECK(panel.reason().contains("crank-driven"));
  CHECK(panel.reason().contains("actuator"));
  CHECK(panel.view()->drawnVectors().empty());
  // Back on a crank-driven linkage, the polygons come back.
  doc.reset(*k::designForExample("thesis-crank-rocker"));
  CHECK(panel.polygons().has_value());
  CHECK(panel.reason().isEmpty());
}

TEST_CASE("at a toggle, where rates do not exist, the panel shows the core's reason", "[ui][classroom]") {
  MechanismDocument doc;
  doc.reset(linkwright::testing::fourBar({40.0, 30.0, 20.0, 25.0}));  // non-Grashof: it stops at toggles
  PolygonPanel panel(&doc);
  doc.setCrankAngle(doc.analysis().inputRange.ranges[0].to);
  REQUIRE(doc.poseStatus() == k::PoseStatus::Singular);
  CHECK_FALSE(panel.polygons().has_value());
  const auto core = k::polygonsAt(doc.mechanism(), {doc.crankAngle(), doc.design().omega, doc.design().alpha});
  REQUIRE_FALSE(static_cast<bool>(core));
  CHECK(panel.reason().contains(QString::fromStdString(core.error().message)));
  CHECK(panel.view()->drawnVectors().empty());
}

TEST_CASE("the main window's Polygons tab follows the crank while shown", "[ui][classroom]") {
  MainWindow window;
  auto* tabs = window.findChild<QTabWidget*>("AnalysisTabs");
  REQUIRE(tabs->tabText(3) == "Polygons");
  tabs->setCurrentIndex(3);
  MechanismDocument* doc = window.document();
  doc->setCrankAngle(k::degToRad(47.0));
  const k::VectorPolygon exact = k::velocityPolygon(doc->mechanism(), solverPose(*doc));
  REQUIRE(window.polygonPanel()->polygons().has_value());
  CHECK(window.polygonPanel()->view()->drawnVectors().back().to.isApprox(exact.vectors.back().to, 1e-12));
  // Hidden, it waits; shown again, it catches up.
  tabs->setCurrentIndex(0);
  doc->setCrankAngle(k::degToRad(120.0));
  tabs->setCurrentIndex(3);
  const k::VectorPolygon later = k::velocityPolygon(doc->mechanism(), solverPose(*doc));
  CHECK(window.polygonPanel()->view()->drawnVectors().back().to.isApprox(later.vectors.back().to, 1e-12));
}
