// The force plots: the torque curve holds the core's torque at every solved sample, one
// magnitude curve per joint, the polar diagram one point per solved sample on equal scales,
// and the cursor and polar dot follow the crank.
#include "ui/plots/force_plot_panel.h"

#include "ui/document/force_results.h"
#include "ui/document/mechanism_document.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/polar_load_view.h"

#include "kinematics/design/design.h"
#include "kinematics/dynamics/inverse_dynamics.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <QComboBox>
#include <QScatterSeries>
#include <QSignalSpy>
#include <QValueAxis>

#include "tests/support/catch.h"

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

std::size_t okSamples(const k::ForceSweep& f) {
  std::size_t n = 0;
  for (std::size_t j = 0; j < f.size(); ++j) n += f.ok(j) ? 1 : 0;
  return n;
}

QList<QPointF> plotted(const CurveItem& line) {
  QList<QPointF> points;
  for (const QList<QPointF>& run : line.runs()) points += run;
  return points;
}

// A document on `design` with forces on and the force plots shown.
struct ShownForces {
  MechanismDocument doc;
  ForceResults forces{&doc};
  ForcePlotPanel panel{&doc, &forces};

  explicit ShownForces(const k::Design& design) {
    forces.setThreading(ForceResults::Threading::GuiThread);  // each change's cycle at once
    doc.reset(design);
    forces.setEnabled(true);
    panel.resize(900, 600);
    panel.show();
  }
};

}  // namespace

TEST_CASE("the force plots show the core's torque, joint magnitudes and polar loci", "[forces][plots]") {
  ShownForces shown(*k::designForExample("funsho-fourbar"));
  MechanismDocument& doc = shown.doc;
  ForceResults& forces = shown.forces;
  ForcePlotPanel& panel = shown.panel;
  const k::ForceSweep& f = *forces.cycleForces();
  const k::SweepResult& s = *forces.cycleSweep();

  const QList<QPointF> torque = panel.torqueChart()->samples(0);
  REQUIRE(static_cast<std::size_t>(torque.size()) == okSamples(f));
  CHECK(torque.front().x() == k::radToDeg(s.inputAngle.front()));
  CHECK(torque.front().y() == f.driveTorque.front());

  REQUIRE(panel.joints().size() == f.bodies.revolutes.size());
  for (std::size_t i = 0; i < panel.joints().size(); ++i)
    CHECK(static_cast<std::size_t>(panel.jointChart()->samples(i).size()) == okSamples(f));

  SECTION("the polar diagram has one point per Ok sample, on equal scales") {
    // Each pin joint, then the shaking force.
    REQUIRE(panel.jointSelector()->count() == static_cast<int>(f.bodies.revolutes.size()) + 1);
    for (int joint = 0; joint + 1 < panel.jointSelector()->count(); ++joint) {
      panel.jointSelector()->setCurrentIndex(joint);
      CHECK(static_cast<std::size_t>(panel.polarView()->pointCount()) == okSamples(f));
      const QList<QPointF> locus = plotted(*panel.polarView()->locus());
      CHECK(locus.front() == QPointF(f.revolute[static_cast<std::size_t>(joint)][0].x(),
                                     f.revolute[static_cast<std::size_t>(joint)][0].y()));
    }
    CHECK(panel.polarView()->xScale() == Approx(panel.polarView()->yScale()).epsilon(1e-6));
    panel.jointSelector()->setCurrentIndex(panel.jointSelector()->count() - 1);
    CHECK(panel.jointSelector()->currentText() == "the shaking force");
    CHECK(static_cast<std::size_t>(panel.polarView()->pointCount()) == okSamples(f));
    CHECK(plotted(*panel.polarView()->locus()).front() == QPointF(f.shakingForce[0].x(), f.shakingForce[0].y()));
  }
  SECTION("the shaking charts hold the core's shaking force and moment, and their peaks") {
    for (std::size_t curve = 0; curve < 3; ++curve)
      REQUIRE(static_cast<std::size_t>(panel.shakingChart()->samples(curve).size()) == okSamples(f));
    double peak = 0.0, moment = 0.0;
    std::size_t at = 0;
    for (std::size_t j = 0; j < f.size(); ++j) {
      CHECK(panel.shakingChart()->samples(0)[static_cast<qsizetype>(j)].y() == f.shakingForce[j].x());
      CHECK(panel.shakingChart()->samples(1)[static_cast<qsizetype>(j)].y() == f.shakingForce[j].y());
      CHECK(panel.shakingChart()->samples(2)[static_cast<qsizetype>(j)].y() == f.shakingForce[j].norm());
      CHECK(panel.shakingMomentChart()->samples(0)[static_cast<qsizetype>(j)].y() == f.shakingMoment[j]);
      if (f.shakingForce[j].norm() > peak) {
        peak = f.shakingForce[j].norm();
        at = j;
      }
      if (std::abs(f.shakingMoment[j]) > std::abs(moment)) moment = f.shakingMoment[j];
    }
    CHECK(panel.shakingMomentChart()->chart()->title() == "Shaking moment about O2");
    // The peaks are refined between samples: at least the best sample, within a step of it, and
    // the forces solved afresh at the angle found have that size.
    const k::ShakingPeaks* refined = forces.shakingPeaks();
    REQUIRE(refined != nullptr);
    const double step = s.inputAngle[1] - s.inputAngle[0];
    CHECK(refined->force.value >= peak);
    CHECK(refined->force.value == Approx(peak).epsilon(1e-3));
    CHECK(std::abs(refined->force.inputAngle - s.inputAngle[at]) <= step);
    CHECK(std::abs(refined->moment.value) >= std::abs(moment));
    const k::Design& d = doc.design();
    const auto pose = k::solvePose(d.mechanism, {refined->force.inputAngle, d.omega, d.alpha});
    REQUIRE(pose.ok());
    CHECK(k::forcesAtPose(d.mechanism, d.dynamics, *pose)->shakingForce.norm() ==
          Approx(refined->force.value).epsilon(1e-12));
    const QString text = panel.shakingPeakText();
    CHECK(text.startsWith(QStringLiteral("Peak shaking force %1 N at crank %2°")
                              .arg(QString::number(refined->force.value, 'g', 4),
                                   QString::number(k::radToDeg(refined->force.inputAngle), 'f', 1))));
    CHECK(text.contains(
        QStringLiteral("peak shaking moment %1 N·m about O2").arg(QString::number(refined->moment.value, 'g', 4))));
    CHECK(text.contains(QStringLiteral("refined between the %1 samples").arg(f.size())));
  }
  SECTION("the cursor and the polar dot follow the crank") {
    doc.setCrankAngle(k::degToRad(90.0));
    REQUIRE(panel.torqueChart()->cursorX().has_value());
    CHECK(*panel.torqueChart()->cursorX() == Approx(90.0));
    CHECK(*panel.jointChart()->cursorX() == Approx(90.0));
    const Eigen::Vector2d at =
        forces.poseForces()->revolute[static_cast<std::size_t>(panel.jointSelector()->currentIndex())];
    REQUIRE(panel.polarView()->currentDot()->count() == 1);
    CHECK(panel.polarView()->currentDot()->at(0) == QPointF(at.x(), at.y()));
  }
}

TEST_CASE("without masses the force plots hide and say why", "[forces][plots]") {
  MechanismDocument doc;
  ForceResults forces(&doc);
  forces.setEnabled(true);
  ForcePlotPanel panel(&doc, &forces);
  CHECK(panel.statusText().contains("Links table"));  // where the masses go
  CHECK(panel.torqueChart()->isHidden() == false);    // its container hides, not the chart itself
  CHECK_FALSE(panel.torqueChart()->isVisibleTo(&panel));
}

TEST_CASE("on a time base the force plots run against time, or the input as the document says",
          "[forces][plots][law]") {
  k::Design timed = *k::designForExample("funsho-fourbar");
  timed.time = k::TimeBase{k::CycloidalRise{0.0, 2.0 * k::kPi, 0.5}, 0.0, 0.5};
  ShownForces shown(timed);
  MechanismDocument& doc = shown.doc;
  ForcePlotPanel& panel = shown.panel;
  const k::SweepResult& s = *shown.forces.cycleSweep();
  REQUIRE(s.time.size() == s.size());
  QList<QPointF> torque = panel.torqueChart()->samples(0);
  REQUIRE_FALSE(torque.isEmpty());
  CHECK(torque.front().x() == s.time.front());
  CHECK(torque.back().x() == 0.5);  // the law's end time
  CHECK(panel.torqueChart()->xAxis()->titleText() == "time [s]");
  doc.setTime(0.25);
  CHECK(panel.torqueChart()->cursorX() == 0.25);
  doc.setPlotAxis(PlotAxis::Input);
  torque = panel.torqueChart()->samples(0);
  CHECK(torque.back().x() == Approx(360.0).margin(1e-12));
  CHECK(panel.torqueChart()->xAxis()->titleText() == "crank angle [deg]");
}

TEST_CASE("an arm's force chart shows its joint torques, an actuator's its force", "[forces][plots][driven]") {
  k::Design arm = *k::designForExample("seed-arm");
  arm.dynamics.links = {{"upper", 2.0, k::LinkFramePoint{0.15, 0.0}, 0.02},
                        {"forearm", 1.5, std::nullopt, std::nullopt}};
  ShownForces shown(arm);
  ForcePlotPanel& panel = shown.panel;
  const k::ForceSweep& f = *shown.forces.cycleForces();
  REQUIRE(okSamples(f) > 0);
  CHECK(panel.torqueChart()->chart()->title() == "Joint torques");
  const QList<QPointF> shoulder = panel.torqueChart()->samples(0);
  const QList<QPointF> elbow = panel.torqueChart()->samples(1);
  REQUIRE(static_cast<std::size_t>(shoulder.size()) == okSamples(f));
  CHECK(shoulder.front() == QPointF(0.0, f.jointTorque.front().x()));  // on the time axis
  CHECK(elbow.back().y() == f.jointTorque.back().y());

  k::Design boom = *k::designForExample("excavator-boom");
  boom.dynamics.links = {{"boom", 50.0, std::nullopt, std::nullopt}};
  shown.doc.reset(boom);
  const k::ForceSweep& g = *shown.forces.cycleForces();
  CHECK(panel.torqueChart()->chart()->title() == "Drive force");
  const QList<QPointF> axial = panel.torqueChart()->samples(0);
  REQUIRE(static_cast<std::size_t>(axial.size()) == okSamples(g));
  CHECK(axial.front().y() == g.driveAlong.front());
}

TEST_CASE("off screen the force plots follow no change, and catch up when shown again", "[forces][plots]") {
  ShownForces shown(*k::designForExample("funsho-fourbar"));
  ForcePlotPanel& panel = shown.panel;
  CurveItem* torque = panel.torqueChart()->curveItem(0);
  REQUIRE(torque != nullptr);
  QSignalSpy replaced(torque, &CurveItem::runsReplaced);
  panel.setOnScreen(false);  // the Kinematics tab chosen, the force arrows still on
  k::Design heavier = shown.doc.design();
  heavier.dynamics.links.front().mass *= 2.0;
  REQUIRE_FALSE(shown.doc.edit(heavier, "mass"));
  CHECK(replaced.isEmpty());
  panel.setOnScreen(true);
  CHECK(replaced.count() == 1);
  const k::ForceSweep& f = *shown.forces.cycleForces();
  const QList<QPointF> now = panel.torqueChart()->samples(0);
  REQUIRE(static_cast<std::size_t>(now.size()) == okSamples(f));
  CHECK(now.back().y() == f.driveTorque.back());
}
