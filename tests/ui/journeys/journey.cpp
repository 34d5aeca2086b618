#include "tests/ui/journeys/journey.h"

#include "ui/canvas/instant_centres_item.h"
#include "ui/canvas/label_item.h"
#include "ui/canvas/linkage_scene.h"
#include "ui/canvas/linkage_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/message_banner.h"
#include "ui/panels/analysis_panel.h"
#include "ui/panels/motion_panel.h"
#include "ui/panels/refusal_label.h"
#include "ui/plots/plot_axes.h"
#include "ui/readout_label.h"

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/design/design.h"
#include "kinematics/design/design_analysis.h"
#include "kinematics/model/units.h"
#include "tests/support/catch.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QGraphicsLayout>
#include <QGraphicsTextItem>
#include <QGuiApplication>
#include <QHeaderView>
#include <QLabel>
#include <QLegend>
#include <QLegendMarker>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSlider>
#include <QTabBar>
#include <QTest>
#include <QTextDocumentFragment>
#include <QTimer>
#include <QValueAxis>

#include <cmath>
#include <functional>

namespace linkwright::test {
namespace k = kinematics;

namespace {

QString plain(QString text) {
  text.remove(QLatin1Char('&'));
  if (text.endsWith(QStringLiteral("…"))) text.chop(1);
  return text.trimmed();
}

QAction* findAction(const QList<QAction*>& actions, const QStringList& path) {
  for (QAction* action : actions) {
    if (plain(action->text()) != path.front()) continue;
    if (path.size() == 1) return action;
    if (QMenu* sub = action->menu()) return findAction(sub->actions(), path.mid(1));
  }
  return nullptr;
}

QString grashofWord(k::GrashofClass c) {
  switch (c) {
  case k::GrashofClass::CrankRocker: return QStringLiteral("Crank-rocker");
  case k::GrashofClass::DoubleCrank: return QStringLiteral("Double-crank");
  case k::GrashofClass::DoubleRocker: return QStringLiteral("Double-rocker");
  case k::GrashofClass::ChangePoint: return QStringLiteral("Change point");
  case k::GrashofClass::TripleRocker: return QStringLiteral("Triple-rocker");
  }
  return {};
}

}  // namespace

bool wholeInSight(const QWidget* w) {
  return w->isVisible() && !w->visibleRegion().isEmpty() && w->visibleRegion().boundingRect() == w->rect();
}

QScreen* journeyScreen(const QString& name) {
  for (QScreen* screen : QGuiApplication::screens())
    if (screen->name() == name) return screen;
  FAIL("no screen " << name.toStdString() << " (the journeys' runner reads journeys/screens.json)");
  return nullptr;
}

Journey::Journey(QScreen* screen) {
  // Where a window manager would open it on that screen: the window places and sizes itself.
  m_window.setScreen(screen);
  m_window.fitToScreen();
  m_window.show();
  REQUIRE(QTest::qWaitForWindowExposed(&m_window));
  m_window.activateWindow();
  REQUIRE(QTest::qWaitForWindowActive(&m_window));
  settle();
}

Journey::Journey(QSize size) {
  m_window.resize(size);
  m_window.show();
  REQUIRE(QTest::qWaitForWindowExposed(&m_window));
  m_window.activateWindow();
  REQUIRE(QTest::qWaitForWindowActive(&m_window));
  settle();
}

void Journey::menu(const QStringList& path) {
  CAPTURE(path.join(QStringLiteral(" ▸ ")).toStdString());
  QAction* action = findAction(m_window.menuBar()->actions(), path);
  REQUIRE(action != nullptr);
  REQUIRE(action->isEnabled());
  action->trigger();
  settle();
}

void Journey::example(const std::string& name) {
  auto* action = m_window.findChild<QAction*>(QString::fromStdString("example_" + name));
  REQUIRE(action != nullptr);
  action->trigger();
  settle();
}

void Journey::key(int key, Qt::KeyboardModifiers modifiers) {
  // A closed dialog leaves no active window on the offscreen platform, where a window system
  // would give the main window back its activation (and its shortcuts).
  if (QApplication::activeWindow() == nullptr) {
    m_window.activateWindow();
    REQUIRE(QTest::qWaitForWindowActive(&m_window));
  }
  QWidget* target = QApplication::focusWidget() != nullptr ? QApplication::focusWidget() : &m_window;
  QTest::keyClick(target, static_cast<Qt::Key>(key), modifiers);
  settle();
}

void Journey::type(QWidget* field, const QString& text) {
  REQUIRE(field != nullptr);
  QTest::mouseClick(field, Qt::LeftButton, Qt::NoModifier, field->rect().center());
  if (auto* spin = qobject_cast<QAbstractSpinBox*>(field)) spin->selectAll();
  if (auto* line = qobject_cast<QLineEdit*>(field)) line->selectAll();
  QTest::keyClicks(QApplication::focusWidget(), text);
  QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
  settle();
}

void Journey::whenModalOpens(std::function<bool(QWidget*)> answer) {
  auto* poll = new QTimer(&m_window);
  poll->setInterval(10);
  QObject::connect(poll, &QTimer::timeout, poll, [poll, answer = std::move(answer)] {
    QWidget* modal = QApplication::activeModalWidget();
    if (modal == nullptr || !modal->isVisible() || !answer(modal)) return;
    poll->stop();
    poll->deleteLater();
  });
  poll->start();
}

void Journey::answerFileDialog(const QString& path) {
  whenDialogOpens<QFileDialog>([path](QFileDialog* files) {
    auto* name = files->findChild<QLineEdit*>("fileNameEdit");
    REQUIRE(name != nullptr);
    name->setText(path);
    QTest::keyClick(name, Qt::Key_Return);
  });
}

void Journey::clickOk(QWidget* dialog) {
  auto* buttons = dialog->findChild<QDialogButtonBox*>();
  REQUIRE(buttons != nullptr);
  QPushButton* ok = buttons->button(QDialogButtonBox::Ok);
  if (ok == nullptr) ok = buttons->button(QDialogButtonBox::Save);
  REQUIRE(ok != nullptr);
  QTest::mouseClick(ok, Qt::LeftButton);
}

void Journey::settle() {
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  m_window.settle();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
}

void Journey::check(const std::string& step) {
  INFO("after: " << step << " (" << m_window.document()->design().kind << ")");
  settle();
  checkMessages();
  checkTitle();
  checkReadouts();
  checkNoNonFinite();
  checkViewsDraw();
  checkNotClipped();
  m_refusalExpected = m_bannerExpected = m_fitted = false;
}

void Journey::checkMessages() {
  for (const ui::RefusalLabel* refusal : m_window.findChildren<ui::RefusalLabel*>()) {
    if (!refusal->isVisibleTo(&m_window) || refusal->refusal().isEmpty()) continue;
    CAPTURE(refusal->refusal().toStdString());
    CHECK(m_refusalExpected);
  }
  CAPTURE(m_window.banner()->text().toStdString());
  CHECK((m_window.banner()->isVisibleTo(&m_window) && !m_window.banner()->text().isEmpty()) == m_bannerExpected);
}

void Journey::checkTitle() {
  const QString title = m_window.windowTitle();
  CAPTURE(title.toStdString());
  const QString path = m_window.document()->filePath();
  if (path.isEmpty()) CHECK(title.contains(QStringLiteral("(not saved)")));
  else CHECK(title.startsWith(QFileInfo(path).fileName()));
  CHECK_FALSE(title.contains(QStringLiteral("Untitled")));
  CHECK(title.endsWith(QStringLiteral("— Linkwright")));
}

void Journey::checkReadouts() {
  const k::Design& design = m_window.document()->design();
  const auto grid = k::sweep(design.mechanism, k::designSweepSpec(design));
  REQUIRE(grid);
  const k::DesignAnalysis core = k::analyseDesign(design.mechanism, *grid);
  const ui::AnalysisPanel& strip = *m_window.analysisPanel();
  CAPTURE(strip.grashofText().toStdString(), strip.timeRatioText().toStdString());
  if (core.grashof) CHECK(strip.grashofText().contains(grashofWord(core.grashof->category)));
  const std::optional<double> ratio = core.grashof       ? core.limits.timeRatio
                                      : core.quickReturn ? std::optional<double>(core.quickReturn->timeRatio)
                                                         : std::nullopt;
  if (ratio) CHECK(strip.timeRatioText().startsWith(QString::number(*ratio, 'f', 4)));
  else if (!core.grashof) CHECK(strip.timeRatioText().isEmpty());
  // The motion bar shows the crank where the document has it.
  if (!m_window.document()->onTimeBase() && k::inputKind(design.mechanism) == k::InputKind::Angle) {
    const double deg = k::radToDeg(std::remainder(m_window.document()->crankAngle(), 2.0 * k::kPi));
    CAPTURE(m_window.motionPanel()->positionText().toStdString(), deg);
    CHECK(m_window.motionPanel()->positionText().contains(QString::number(std::abs(deg), 'f', 1)));
  }
}

void Journey::checkNoNonFinite() {
  static const QRegularExpression nonFinite(QStringLiteral("\\b(nan|inf)\\b"),
                                            QRegularExpression::CaseInsensitiveOption);
  QStringList texts{m_window.windowTitle()};
  for (const QLabel* label : m_window.findChildren<QLabel*>())
    if (label->isVisibleTo(&m_window)) texts << label->text();
  for (const ui::ReadoutLabel* label : m_window.findChildren<ui::ReadoutLabel*>())
    if (label->isVisibleTo(&m_window)) texts << label->text();
  for (const QAbstractSpinBox* spin : m_window.findChildren<QAbstractSpinBox*>())
    if (spin->isVisibleTo(&m_window)) texts << spin->text();
  for (const QString& text : texts) {
    CAPTURE(text.toStdString());
    CHECK_FALSE(nonFinite.match(text).hasMatch());
  }
}

void Journey::checkViewsDraw() {
  QAction* centres = findAction(m_window.menuBar()->actions(), {"View", "Instant centres and centrodes"});
  REQUIRE(centres != nullptr);
  if (!centres->isChecked()) return;
  const auto* scene = dynamic_cast<const ui::LinkageScene*>(m_window.canvas()->linkageScene());
  REQUIRE(scene != nullptr);
  const auto core = k::instantCentres(m_window.document()->mechanism(), m_window.document()->pose());
  if (!core || core->centres.empty()) return;
  const ui::InstantCentresItem& item = *scene->instantCentresItem();
  CAPTURE(item.reason().toStdString());
  REQUIRE(item.centres().has_value());
  CHECK(item.centres()->centres.size() == core->centres.size());
}

void Journey::checkNotClipped() {
  const ui::AnalysisPanel* strip = m_window.analysisPanel();
  CHECK(wholeInSight(strip));
  for (QWidget* value : strip->findChildren<QWidget*>()) {
    if (!value->isVisibleTo(&m_window)) continue;
    const auto* label = qobject_cast<const QLabel*>(value);
    const QRect seen = value->visibleRegion().boundingRect();
    CAPTURE(value->metaObject()->className(), label != nullptr ? label->text().toStdString() : std::string(),
            value->width(), value->height(), seen.width(), seen.height(), m_window.width(), m_window.height());
    CHECK(wholeInSight(value));
    CHECK(value->height() >= value->heightForWidth(value->width()));
  }
  CHECK(wholeInSight(m_window.motionPanel()->playButton()));
  if (!m_fitted) return;
  ui::LinkageView* view = m_window.canvas();
  const QRect viewport = view->viewport()->rect();
  std::vector<QRectF> names;
  for (QGraphicsItem* item : view->scene()->items()) {
    const auto* label = dynamic_cast<const ui::LabelItem*>(item);
    if (label == nullptr || !label->isVisible() || label->text().isEmpty()) continue;
    const QRectF drawn = label->deviceTransform(view->viewportTransform()).mapRect(label->boundingRect());
    CAPTURE(label->text().toStdString(), drawn.left(), drawn.top(), drawn.right(), drawn.bottom(), viewport.width(),
            viewport.height());
    CHECK(QRectF(viewport).adjusted(-1, -1, 1, 1).contains(drawn));
    names.push_back(drawn);
  }
  // The instant centres' labels, as the canvas paints them: inside, off the point names and
  // off each other (I₂₃ was drawn over B).
  const auto* scene = dynamic_cast<const ui::LinkageScene*>(view->linkageScene());
  if (scene == nullptr || !scene->instantCentresItem()->isVisible()) return;
  view->viewport()->grab();  // paints
  const std::vector<QRectF>& centres = scene->instantCentresItem()->drawnLabels();
  for (std::size_t a = 0; a < centres.size(); ++a) {
    CAPTURE(a, centres[a].left(), centres[a].top(), centres[a].width(), centres[a].height());
    CHECK(QRectF(viewport).adjusted(-1, -1, 1, 1).contains(centres[a]));
    for (const QRectF& name : names) CHECK_FALSE(name.intersects(centres[a]));
    for (std::size_t b = a + 1; b < centres.size(); ++b) CHECK_FALSE(centres[b].intersects(centres[a]));
  }
}

void Journey::checkFitsScreen(const std::string& step) {
  check(step);
  INFO("after: " << step << " (" << m_window.document()->design().kind << ", " << m_window.width() << "×"
                 << m_window.height() << (m_window.presentationMode() ? ", presenting" : "") << ")");
  checkInsideScreen();
  checkWidgetsWhole();
  checkChartsWhole();
}

void Journey::checkInsideScreen() {
  QScreen* screen = m_window.screen();
  REQUIRE(screen != nullptr);
  const QRect room = m_window.presentationMode() ? screen->geometry() : screen->availableGeometry();
  const QRect frame = m_window.frameGeometry();
  const QSize least = m_window.minimumSizeHint().expandedTo(m_window.minimumSize());
  CAPTURE(screen->name().toStdString(), room.width(), room.height(), frame.x(), frame.y(), frame.width(),
          frame.height(), least.width(), least.height());
  CHECK(room.contains(frame));
  // Nothing the window holds may ask for more than the screen has: a layout's minimum is a
  // top-level window's minimum, and Qt grows the window to it (1075 px on the Forces tab).
  CHECK(least.width() <= room.width());
  CHECK(least.height() <= room.height());
}

namespace {

// What a widget says it needs, once the layout has given it its size: a label or a button its
// text's, an input its minimumSizeHint.
bool inTabBarOrScrollBar(const QWidget* widget) {
  for (const QObject* o = widget->parent(); o != nullptr; o = o->parent())
    if (qobject_cast<const QTabBar*>(o) != nullptr || qobject_cast<const QScrollBar*>(o) != nullptr) return true;
  return false;
}

QString describe(const QWidget* w) {
  return QStringLiteral("%1 '%2' %3×%4 wants %5×%6")
      .arg(QString::fromLatin1(w->metaObject()->className()), w->objectName())
      .arg(w->width())
      .arg(w->height())
      .arg(w->minimumSizeHint().width())
      .arg(w->minimumSizeHint().height());
}

}  // namespace

void Journey::checkWidgetsWhole() {
  for (const QWidget* widget : m_window.findChildren<QWidget*>()) {
    if (!widget->isVisible() || widget->window() != &m_window || inTabBarOrScrollBar(widget)) continue;
    if (const auto* label = qobject_cast<const QLabel*>(widget)) {
      if (label->text().isEmpty()) continue;
      const QString text = label->textFormat() == Qt::RichText || Qt::mightBeRichText(label->text())
                               ? QTextDocumentFragment::fromHtml(label->text()).toPlainText()
                               : label->text();
      CAPTURE(describe(label).toStdString(), text.toStdString(), label->toolTip().toStdString());
      if (text.endsWith(QStringLiteral("…"))) CHECK(label->toolTip().contains(text.chopped(1)));
      if (label->wordWrap()) {
        CHECK(label->height() >= label->heightForWidth(label->width()));
      } else {
        CHECK(label->width() >= label->minimumSizeHint().width());
        CHECK(label->height() >= label->minimumSizeHint().height());
      }
      continue;
    }
    if (const auto* button = qobject_cast<const QAbstractButton*>(widget)) {
      if (button->inherits("QTableCornerButton") || button->text().isEmpty()) continue;
      CAPTURE(describe(button).toStdString(), button->text().toStdString());
      CHECK(button->width() >= button->minimumSizeHint().width());
      CHECK(button->height() >= button->minimumSizeHint().height());
      continue;
    }
    const bool input = qobject_cast<const QAbstractSpinBox*>(widget) != nullptr ||
                       qobject_cast<const QComboBox*>(widget) != nullptr ||
                       qobject_cast<const QSlider*>(widget) != nullptr ||
                       (qobject_cast<const QAbstractItemView*>(widget) != nullptr &&
                        qobject_cast<const QHeaderView*>(widget) == nullptr) ||
                       (qobject_cast<const QLineEdit*>(widget) != nullptr &&
                        qobject_cast<const QAbstractSpinBox*>(widget->parent()) == nullptr &&
                        qobject_cast<const QComboBox*>(widget->parent()) == nullptr);
    if (!input) continue;
    CAPTURE(describe(widget).toStdString());
    CHECK(widget->width() >= widget->minimumSizeHint().width());
    CHECK(widget->height() >= widget->minimumSizeHint().height());
  }
}

void Journey::checkChartsWhole() {
  for (const QChartView* view : m_window.findChildren<QChartView*>()) {
    if (!view->isVisible() || view->window() != &m_window) continue;
    QChart* chart = view->chart();
    // As the next paint lays it out: a chart's layout is activated by a posted event.
    chart->layout()->activate();
    // The axes' titles as our axes item draws them: never "a [..." (the unit lost).
    if (const ui::PlotAxesItem* axes = ui::plotAxes(chart)) {
      for (const Qt::Orientation o : {Qt::Horizontal, Qt::Vertical}) {
        const QList<QAbstractAxis*> list = chart->axes(o);
        if (list.isEmpty() || !axes->titleShown(o) || list.front()->titleText().isEmpty()) continue;
        CAPTURE(chart->title().toStdString(), list.front()->titleText().toStdString(), axes->title(o).toStdString(),
                chart->plotArea().width(), chart->plotArea().height());
        // Whole, or its name cut short: its unit always whole.
        const QString full = list.front()->titleText(), drawn = axes->title(o);
        const auto bracket = full.lastIndexOf(QLatin1Char('['));
        if (drawn != full) REQUIRE(bracket >= 0);
        if (drawn != full) CHECK(drawn.endsWith(full.mid(bracket)));
      }
    }
    // The legend's entries: whole, or elided by Qt with the whole name in the entry's tooltip;
    // and each inside the legend, not cut off at its foot on a short chart.
    const QLegend* legend = chart->legend();
    if (!legend->isVisible()) continue;
    QStringList shown;
    const QRectF legendArea = legend->sceneBoundingRect().adjusted(-1, -1, 1, 1);
    std::function<void(const QGraphicsItem*)> collect = [&](const QGraphicsItem* item) {
      if (const auto* t = dynamic_cast<const QGraphicsTextItem*>(item); t != nullptr && t->isVisible()) {
        shown << t->toPlainText();
        const QRectF text = t->sceneBoundingRect();
        CAPTURE(view->height(), view->minimumHeight(), view->parentWidget()->height());
        CAPTURE(chart->title().toStdString(), t->toPlainText().toStdString(), text.top(), text.bottom(),
                legendArea.top(), legendArea.bottom());
        CHECK(text.top() >= legendArea.top());
        CHECK(text.bottom() <= legendArea.bottom());
      }
      for (const QGraphicsItem* child : item->childItems()) collect(child);
    };
    collect(legend);
    for (const QLegendMarker* marker : legend->markers()) {
      if (!marker->isVisible() || shown.contains(marker->label())) continue;
      CAPTURE(chart->title().toStdString(), marker->label().toStdString(), shown.join(" | ").toStdString());
      CHECK(legend->showToolTips());
    }
  }
}

}  // namespace linkwright::test
