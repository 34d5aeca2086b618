// The answers are seen without scrolling on a teaching laptop (1366×768, a window of
// 1366×700 once the desktop's bars are taken): a new user found the Play controls and the
// Analysis box (Grashof class, time ratio, transmission angle) below the fold of the side panel.
// For every example, the real window at that size shows the whole analysis strip and the
// motion bar unclipped, none of their values cut off, and every control of the side panel can
// still be scrolled into sight.

#include "tests/ui/journeys/journey.h"

#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"
#include "ui/panels/analysis_panel.h"
#include "ui/panels/motion_panel.h"
#include "ui/readout_label.h"

#include "kinematics/design/examples.h"
#include "tests/support/catch.h"

#include <QApplication>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSlider>
#include <QTest>

#include <string>

using namespace linkwright;

using test::wholeInSight;

TEST_CASE("at 1366×700 the analysis and the motion controls are in sight without scrolling",
          "[ui][window][journey][layout]") {
  test::Journey journey;  // 1366×700
  ui::MainWindow& window = journey.window();
  auto* side = window.findChild<QScrollArea*>("SidePanel");
  REQUIRE(side != nullptr);
  for (const kinematics::Example& e : kinematics::examples()) {
    const std::string& example = e.name;
    CAPTURE(example);
    journey.example(example);
    side->verticalScrollBar()->setValue(0);
    journey.check("Examples ▸ " + example);
    CHECK_FALSE(side->isAncestorOf(window.analysisPanel()));
    CHECK(wholeInSight(window.analysisPanel()));
    CHECK(wholeInSight(window.motionPanel()->playButton()));
    CHECK(wholeInSight(window.motionPanel()->positionSlider()));
    // Every value shown, whole: long ones wrap instead of being cut.
    for (QWidget* value : window.analysisPanel()->findChildren<QWidget*>()) {
      if (!value->isVisibleTo(&window)) continue;
      const auto* readout = qobject_cast<ui::ReadoutLabel*>(value);
      CAPTURE(value->metaObject()->className(), readout ? readout->text().toStdString() : std::string());
      CHECK(wholeInSight(value));
      CHECK(value->height() >= value->heightForWidth(value->width()));
    }
    // The badge names the kind in words ("Stephenson II"), never its file id ("stephenson-ii").
    const std::string& kind = window.document()->design().kind;
    if (kind.find('-') != std::string::npos)
      CHECK_FALSE(window.analysisPanel()->grashofText().contains(QString::fromStdString(kind)));
    // Every control of the side panel can still be reached by scrolling.
    for (QWidget* control : side->widget()->findChildren<QWidget*>()) {
      if (!control->isVisibleTo(side) || control->focusPolicy() == Qt::NoFocus) continue;
      side->ensureWidgetVisible(control);
      QApplication::processEvents();
      CAPTURE(control->metaObject()->className());
      CHECK_FALSE(control->visibleRegion().isEmpty());
    }
  }
}
