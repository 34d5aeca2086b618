// A drag of a joint changes numbers, not the window's shape: no widget is laid out again on
// every move (Qt re-lays out every layout up to the main window when one child asks), and a
// read-out label asks only when its new text needs another line. See ui/quiet_update.h and
// ui/readout_label.h. Nor does the first hint in the status bar.

#include "ui/canvas/linkage_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"
#include "ui/readout_label.h"

#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"

#include "tests/support/catch.h"

#include <QApplication>
#include <QFormLayout>
#include <QStatusBar>
#include <QTest>

#include <cmath>

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

// Counts the layout requests posted to widgets (a chart's own QGraphicsWidget layout is not a
// widget's), naming each receiver.
class LayoutRequests : public QObject {
public:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (event->type() == QEvent::LayoutRequest && watched->isWidgetType())
      receivers << QString::fromLatin1(watched->metaObject()->className()) + "/" + watched->objectName();
    return false;
  }
  QStringList receivers;
};

// Handles what a move posted, and what handling that posted (a layout request climbs one
// widget per round).
void settle() {
  for (int round = 0; round < 6; ++round) {
    QApplication::processEvents();
    QApplication::sendPostedEvents();
  }
}

}  // namespace

TEST_CASE("dragging a joint lays out no widget on every move", "[ui][window][drag]") {
  // A four-bar's C (its lengths editor with sliders) and a six-bar's last joint E (the general
  // dimensions panel).
  const std::string example = GENERATE(as<std::string>{}, "thesis-crank-rocker", "watt-ii");
  CAPTURE(example);
  MainWindow window;
  window.resize(1400, 880);
  window.show();
  REQUIRE(QTest::qWaitForWindowExposed(&window));
  MechanismDocument* doc = window.document();
  doc->reset(*k::designForExample(example));
  QApplication::processEvents();
  LinkageView* canvas = window.canvas();
  const std::size_t joint = doc->fourBar() ? doc->fourBar()->c.index : doc->mechanism().points.size() - 1;
  const Eigen::Vector2d& at = doc->pose().position[joint];
  const QPointF start = canvas->mapFromScene(QPointF(at.x(), at.y()));
  QTest::mousePress(canvas->viewport(), Qt::LeftButton, Qt::NoModifier, start.toPoint());
  // The first move starts the drag (the status bar's hint, the estimate's "measuring…").
  QTest::mouseMove(canvas->viewport(), (start + QPointF(1.0, 1.0)).toPoint());
  settle();
  const k::Design before = doc->design();
  LayoutRequests requests;
  qApp->installEventFilter(&requests);
  // A hand's few pixels around the start, where the crank keeps turning fully: every value in
  // the panels changes, no row appears or goes.
  int movesLaidOut = 0;
  for (int i = 1; i <= 30; ++i) {
    const qsizetype requested = requests.receivers.size();
    QTest::mouseMove(canvas->viewport(),
                     (start + QPointF(12.0 * std::sin(i * 0.1), 8.0 * std::cos(i * 0.13))).toPoint());
    settle();
    movesLaidOut += requests.receivers.size() > requested ? 1 : 0;
  }
  qApp->removeEventFilter(&requests);
  QTest::mouseRelease(canvas->viewport(), Qt::LeftButton, Qt::NoModifier, start.toPoint());
  CHECK_FALSE(doc->design() == before);  // the drag did change the linkage
  // A read-out whose text grows a line asks once (the four-bar's "μ over cycle" does, here);
  // nothing asks on every move.
  CAPTURE(requests.receivers.join(", ").toStdString());
  CHECK(movesLaidOut <= 1);
}

TEST_CASE("the first hover hint in the status bar moves no widget", "[ui][window][drag]") {
  // QMainWindow makes its status bar on the first message; it would then take its height from
  // the content, and every widget would move and be repainted as a drag begins.
  MainWindow window;
  window.resize(1400, 880);
  window.show();
  REQUIRE(QTest::qWaitForWindowExposed(&window));
  settle();
  QWidget* central = window.centralWidget();
  const QRect before = central->geometry();
  emit window.canvas()->statusMessage(QStringLiteral("Drag C: the coupler and rocker follow"));
  settle();
  CHECK(central->geometry() == before);
  CHECK(window.statusBar()->currentMessage() == QStringLiteral("Drag C: the coupler and rocker follow"));
}

TEST_CASE("a read-out label asks for a new layout only when its text needs one", "[ui][readout]") {
  QWidget panel;
  auto* form = new QFormLayout(&panel);
  auto* label = new ReadoutLabel(&panel);
  form->addRow(QStringLiteral("Transmission μ"), label);
  label->setText(QStringLiteral("C 41.3°, E 77.0°"));
  panel.resize(300, 100);
  panel.show();
  REQUIRE(QTest::qWaitForWindowExposed(&panel));
  QApplication::processEvents();
  const int oneLine = label->height();
  LayoutRequests requests;
  panel.installEventFilter(&requests);

  label->setText(QStringLiteral("C 41.4°, E 76.9°"));  // same room
  QApplication::processEvents();
  CHECK(requests.receivers.isEmpty());
  CHECK(label->text() == QStringLiteral("C 41.4°, E 76.9°"));

  // Too long for one line at this width: it wraps, and the form gives it the second line.
  const QString longer = QStringLiteral("C 41.4°, E 76.9°, F 12.5°, G 150.2°, H 33.3°, I 98.7°, J 101.0°");
  label->setText(longer);
  QApplication::processEvents();
  CHECK_FALSE(requests.receivers.isEmpty());
  CHECK(label->height() > oneLine);
  CHECK(label->height() == label->heightForWidth(label->width()));
  CHECK(label->heightForWidth(label->width() / 3) > label->height());

  // Back to one line: the row keeps its height while the texts keep coming (rows below do not
  // jump during a drag), and gives it back when the label's width changes.
  requests.receivers.clear();
  const int twoLines = label->height();
  label->setText(QStringLiteral("C 41.4°"));
  QApplication::processEvents();
  CHECK(requests.receivers.isEmpty());
  CHECK(label->height() == twoLines);
  panel.resize(340, 100);
  QApplication::processEvents();
  CHECK(label->height() == oneLine);

  // A word wider than the label cannot be wrapped, though it fits in the lines held: the label
  // asks for the room of its widest word.
  requests.receivers.clear();
  const QString word(label->width() / label->fontMetrics().horizontalAdvance(QChar(u'W')) + 4, QChar(u'W'));
  label->setText(word);
  QApplication::processEvents();
  CHECK_FALSE(requests.receivers.isEmpty());
  CHECK(label->minimumSizeHint().width() == label->fontMetrics().horizontalAdvance(word));
}
