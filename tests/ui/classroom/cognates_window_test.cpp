// View ▸ Cognates… against the core (kinematics/explore/cognates.h): the three four-bars drawn
// share the coupler point of the designer's pose and keep their links' lengths as the crank
// turns, Play turns the designer's crank, Keep makes a cognate the design (undoably), and a
// linkage without cognates leaves the window saying why with nothing drawn from before.
#include "ui/classroom/cognates_window.h"

#include "ui/classroom/cognates_view.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <QPushButton>
#include <QTest>

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

k::Design withCouplerPoint() {
  return k::fourBarDesign({30.0, 10.0, 35.0, 20.0}, k::Branch::Open, "mm", k::CouplerPointSpec{17.5, 10.0}).value();
}

// The drawn joints against the pose and against each four-bar's own lengths.
void checkDrawn(const CognatesWindow& window, const MechanismDocument& doc) {
  REQUIRE(window.view()->joints().has_value());
  const auto& drawn = *window.view()->joints();
  const Eigen::Vector2d p = doc.pose().position[doc.mechanism().findPoint("P")->index];
  const auto& set = *window.cognates();
  const std::array<const k::CognateFourBar*, 3> fourBars{&set.original, &set.cognates[0], &set.cognates[1]};
  for (std::size_t i = 0; i < 3; ++i) {
    CAPTURE(i);
    const k::FourBarJoints& j = drawn[i];
    const k::FourBarLengths& l = fourBars[i]->fourBar.lengths;
    CHECK((j.p - p).norm() <= 1e-9 * l.frame);  // one coupler point for the three
    CHECK((j.b - j.o2).norm() == Approx(l.crank).epsilon(1e-9));
    CHECK((j.c - j.b).norm() == Approx(l.coupler).epsilon(1e-9));
    CHECK((j.c - j.o4).norm() == Approx(l.rocker).epsilon(1e-9));
    CHECK((j.o4 - j.o2).norm() == Approx(l.frame).epsilon(1e-9));
  }
}

}  // namespace

TEST_CASE("the cognates window draws the three four-bars on one coupler point as the crank turns",
          "[classroom][cognates]") {
  MechanismDocument doc;
  doc.reset(withCouplerPoint());
  CognatesWindow window(&doc);
  window.show();
  REQUIRE(window.cognates().has_value());
  CHECK(window.figuresText().contains("Cognate 2"));
  CHECK(window.figuresText().contains("its crank turns with the original's, 1:1."));
  CHECK(window.figuresText().contains("its crank turns with the original's coupler, at "));
  checkDrawn(window, doc);
  // The curve is P over the designer's cycle, and the frame holds every joint of the three.
  const k::SweepResult& sweep = doc.sweep();
  const std::size_t p = doc.mechanism().findPoint("P")->index;
  REQUIRE(static_cast<std::size_t>(window.view()->curve().size()) == sweep.size());
  CHECK(window.view()->curve().back() == QPointF(sweep.position[p].back().x(), sweep.position[p].back().y()));
  for (const k::FourBarJoints& j : *window.view()->joints())
    for (const Eigen::Vector2d& q : {j.o2, j.o4, j.b, j.c, j.p})
      CHECK(window.view()->extent().adjusted(-1e-9, -1e-9, 1e-9, 1e-9).contains(QPointF(q.x(), q.y())));
  doc.setCrankAngle(k::degToRad(130.0));
  checkDrawn(window, doc);

  // Play turns the designer's crank; the drawing follows.
  const double before = doc.crankAngle();
  window.togglePlay();
  QTest::qWait(5 * 30);
  window.togglePlay();
  CHECK(doc.crankAngle() > before);
  checkDrawn(window, doc);

  // Keep cognate 2: it becomes the design, and Undo brings the original back.
  const k::Design original = doc.design();
  const k::Design kept = window.cognates()->cognates[1].design;
  QTest::mouseClick(window.keepButton(1), Qt::LeftButton);
  CHECK(doc.design() == kept);
  REQUIRE(window.cognates().has_value());  // the kept four-bar has cognates of its own
  checkDrawn(window, doc);
  doc.undoStack()->undo();
  CHECK(doc.design() == original);

  // A four-bar without a coupler point: no cognates, and nothing left of the last drawing.
  doc.reset(k::fourBarDesign({30.0, 10.0, 35.0, 20.0}).value());
  CHECK_FALSE(window.cognates().has_value());
  CHECK(window.figuresText().startsWith("No cognates: "));
  CHECK_FALSE(window.view()->joints().has_value());
  CHECK(window.view()->curve().isEmpty());
  CHECK_FALSE(window.keepButton(0)->isEnabled());
  CHECK_FALSE(window.playButton()->isEnabled());
}
