#include "ui/classroom/cognates_window.h"

#include "ui/classroom/cognates_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/number_text.h"

#include "kinematics/model/units.h"

#include <QHBoxLayout>

#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>
#include <limits>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr int kFrameMs = 30;

QString point(const Eigen::Vector2d& p) { return pointText(p.x(), p.y(), 5); }

QString figures(const k::CognateFourBar& f, const QString& title, const QString& unit) {
  const k::FourBarLengths& l = f.fourBar.lengths;
  QString text = CognatesWindow::tr("%1: pivots %2 and %3 %4; crank %5, coupler %6, rocker %7, frame %8 %4; %9")
                     .arg(title, point(f.crankPivot), point(f.rockerPivot), unit, numberText(l.crank, 'g', 5),
                          numberText(l.coupler, 'g', 5), numberText(l.rocker, 'g', 5), numberText(l.frame, 'g', 5),
                          QString::fromUtf8(k::toString(f.grashof.category).data()));
  text += f.worstTransmission ? CognatesWindow::tr("; worst transmission angle %1°")
                                    .arg(numberText(k::radToDeg(*f.worstTransmission), 'f', 1))
                              : CognatesWindow::tr("; its transmission angle cannot be followed over the cycle");
  switch (f.turnsWith[0]) {
  case k::OriginalLink::Crank: text += CognatesWindow::tr("; its crank turns with the original's, 1:1."); break;
  case k::OriginalLink::Coupler:
    text += f.crankSpeedRatioMin && f.crankSpeedRatioMax
                ? CognatesWindow::tr(
                      "; its crank turns with the original's coupler, at %1 to %2 times the "
                      "original crank's speed.")
                      .arg(numberText(*f.crankSpeedRatioMin, 'g', 3), numberText(*f.crankSpeedRatioMax, 'g', 3))
                : CognatesWindow::tr("; its crank turns with the original's coupler.");
    break;
  case k::OriginalLink::Rocker: text += CognatesWindow::tr("; its crank turns with the original's rocker."); break;
  }
  return text;
}

}  // namespace

CognatesWindow::CognatesWindow(MechanismDocument* document, QWidget* parent)
    : QWidget(parent, Qt::Window), m_document(document), m_view(new CognatesView), m_figures(new QLabel),
      m_play(new QPushButton(tr("Play"))) {
  setWindowTitle(tr("Cognates"));
  m_figures->setWordWrap(true);
  m_figures->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_figures->setObjectName(QStringLiteral("cognateFigures"));
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(m_play);
  buttons->addStretch(1);
  for (int i = 0; i < 2; ++i) {
    m_keep[static_cast<std::size_t>(i)] = new QPushButton(tr("Keep cognate %1 as the design").arg(i + 1));
    buttons->addWidget(m_keep[static_cast<std::size_t>(i)]);
    connect(m_keep[static_cast<std::size_t>(i)], &QPushButton::clicked, this, [this, i] { keep(i); });
  }
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(m_view, 1);
  layout->addWidget(m_figures);
  layout->addLayout(buttons);
  resize(900, 700);

  m_timer.setInterval(kFrameMs);
  connect(&m_timer, &QTimer::timeout, this, [this] { m_document->setCrankAngle(m_document->crankAngle() + kStep); });
  connect(m_play, &QPushButton::clicked, this, &CognatesWindow::togglePlay);
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & (Change::Design | Change::Request)) rebuild();
    else if (what & Change::Motion) followPose();
  });
  rebuild();
}

QString CognatesWindow::figuresText() const { return m_figures->text(); }

void CognatesWindow::togglePlay() {
  if (m_timer.isActive() || !m_set) m_timer.stop();
  else m_timer.start();
  m_play->setText(m_timer.isActive() ? tr("Pause") : tr("Play"));
}

void CognatesWindow::hideEvent(QHideEvent* event) {
  m_timer.stop();
  m_play->setText(tr("Play"));
  QWidget::hideEvent(event);
}

void CognatesWindow::rebuild() {
  auto set = k::cognates(m_document->design());
  const bool any = set.ok();
  for (QPushButton* button : m_keep) button->setEnabled(any);
  m_play->setEnabled(any && !m_document->design().time);
  m_play->setToolTip(m_document->design().time ? tr("The designer's motion law drives the crank: play it there")
                                               : QString());
  if (!any) {
    m_set.reset();
    m_timer.stop();
    m_figures->setTextFormat(Qt::PlainText);
    m_figures->setText(tr("No cognates: %1").arg(QString::fromStdString(set.error().message)));
    m_view->setCurve({}, {});
    m_view->setJoints(std::nullopt);
    return;
  }
  m_set = std::move(*set);
  // The curve and the frame: P over the cycle, and every joint of the three over it.
  const k::SweepResult& sweep = m_document->sweep();
  const k::Mechanism& m = m_document->mechanism();
  const auto p = m.findPoint(m_set->couplerPoint);
  QPolygonF curve;
  QRectF extent;
  // Bounds by hand: QRectF::united ignores a rectangle of no size, as one point is.
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::max()), high = -low;
  const auto grow = [&](const Eigen::Vector2d& q) {
    low = low.cwiseMin(q);
    high = high.cwiseMax(q);
  };
  const k::FourBarStructure& f = m_set->original.fourBar;
  // The moving joints from the sweep's columns; the ground pivots, which a sweep need not
  // store, from the pose (they do not move).
  const auto hasColumn = [&](k::PointId id) {
    return id.index < sweep.position.size() && sweep.position[id.index].size() == sweep.size();
  };
  const k::Pose& pose = m_document->pose();
  const bool complete =
      p && hasColumn(f.b) && hasColumn(f.c) && hasColumn(*p) && std::max(f.o2.index, f.o4.index) < pose.position.size();
  for (std::size_t j = 0; complete && j < sweep.size(); ++j) {
    if (!sweep.assembled(j)) continue;
    const k::FourBarJoints at{pose.position[f.o2.index], pose.position[f.o4.index], sweep.position[f.b.index][j],
                              sweep.position[f.c.index][j], sweep.position[p->index][j]};
    curve << QPointF(at.p.x(), at.p.y());
    const k::CognateJoints c = k::cognateJoints(at);
    for (const k::FourBarJoints& four : {at, c.first, c.second})
      for (const Eigen::Vector2d& q : {four.o2, four.o4, four.b, four.c, four.p}) grow(q);
  }
  if (!curve.isEmpty()) extent = QRectF(QPointF(low.x(), low.y()), QPointF(high.x(), high.y()));
  m_view->setCurve(curve, extent);
  const QString unit = QString::fromStdString(m.lengthUnit);
  // Each line keyed by a square of the colour its four-bar is drawn in.
  const auto line = [&](int i, const k::CognateFourBar& fourBar, const QString& title) {
    return QStringLiteral("<span style=\"color:%1\">&#9632;</span> ").arg(CognatesView::colorOf(i).name()) +
           figures(fourBar, title, unit).toHtmlEscaped();
  };
  m_figures->setTextFormat(Qt::RichText);
  m_figures->setText(line(0, m_set->original, tr("Original")) + "<br>" +
                     line(1, m_set->cognates[0], tr("Cognate 1 (pivots O2 and the third pivot O6)")) + "<br>" +
                     line(2, m_set->cognates[1], tr("Cognate 2 (pivots O6 and O4)")));
  followPose();
}

void CognatesWindow::followPose() {
  if (!m_set) return;
  const k::Pose& pose = m_document->pose();
  const auto p = m_document->mechanism().findPoint(m_set->couplerPoint);
  const k::FourBarStructure& f = m_set->original.fourBar;
  if (!p || !pose.assembled || p->index >= pose.position.size()) {
    m_view->setJoints(std::nullopt);
    return;
  }
  const k::FourBarJoints at{pose.position[f.o2.index], pose.position[f.o4.index], pose.position[f.b.index],
                            pose.position[f.c.index], pose.position[p->index]};
  const k::CognateJoints c = k::cognateJoints(at);
  m_view->setJoints(std::array<k::FourBarJoints, 3>{at, c.first, c.second});
}

void CognatesWindow::keep(int cognate) {
  if (!m_set) return;
  const k::Design design = m_set->cognates[static_cast<std::size_t>(cognate)].design;
  if (const auto why = m_document->replace(design, tr("Keep cognate %1").arg(cognate + 1)))
    m_figures->setText(m_figures->text() + "<br>" + why->toHtmlEscaped());
}

}  // namespace linkwright::ui
