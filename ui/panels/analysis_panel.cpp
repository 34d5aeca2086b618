#include "ui/panels/analysis_panel.h"

#include "ui/document/mechanism_document.h"

#include "kinematics/model/units.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QString degrees(double radians, int decimals = 2) { return QString::number(k::radToDeg(radians), 'f', decimals) + "°"; }

QString className(k::GrashofClass c) {
  switch (c) {
  case k::GrashofClass::CrankRocker: return QObject::tr("Crank-rocker");
  case k::GrashofClass::DoubleCrank: return QObject::tr("Double-crank (drag link)");
  case k::GrashofClass::DoubleRocker: return QObject::tr("Double-rocker");
  case k::GrashofClass::ChangePoint: return QObject::tr("Change point");
  case k::GrashofClass::TripleRocker: return QObject::tr("Triple-rocker (non-Grashof)");
  }
  return {};
}

// Green for a Grashof linkage whose crank turns, amber for the rest.
QString badgeColour(const k::GrashofReport& g) { return g.inputFullyRotates ? "#1b7f3b" : "#a15c00"; }

} // namespace

AnalysisPanel::AnalysisPanel(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_badge(new QLabel(this)), m_sums(new QLabel(this)),
      m_mobility(new QLabel(this)), m_range(new QLabel(this)), m_transmissionNow(new QLabel(this)),
      m_transmissionRange(new QLabel(this)), m_limits(new QLabel(this)), m_timeRatio(new QLabel(this)),
      m_warning(new QLabel(this)) {
  auto* layout = new QVBoxLayout(this);
  auto* box = new QGroupBox(tr("Analysis"), this);
  auto* form = new QFormLayout(box);
  m_badge->setTextFormat(Qt::RichText);
  form->addRow(m_badge);
  form->addRow(tr("S + L, P + Q"), m_sums);
  form->addRow(tr("Mobility"), m_mobility);
  form->addRow(tr("Crank range"), m_range);
  form->addRow(tr("Transmission μ"), m_transmissionNow);
  form->addRow(tr("μ over cycle"), m_transmissionRange);
  form->addRow(tr("Rocker limits"), m_limits);
  form->addRow(tr("Time ratio"), m_timeRatio);
  for (QLabel* l : {m_sums, m_range, m_transmissionRange, m_limits, m_timeRatio}) l->setWordWrap(true);
  m_warning->setWordWrap(true);
  m_warning->setStyleSheet("color: #a15c00;");
  form->addRow(m_warning);
  layout->addWidget(box);
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & Change::Design) refreshDesign();
    refreshMotion();
  });
  refreshDesign();
  refreshMotion();
}

QString AnalysisPanel::grashofText() const { return m_badge->text(); }
QString AnalysisPanel::transmissionNowText() const { return m_transmissionNow->text(); }

void AnalysisPanel::refreshDesign() {
  const DesignAnalysis& a = m_document->analysis();
  const QString unit = QString::fromStdString(m_document->design().lengthUnit);
  const k::GrashofReport& g = a.grashof;
  m_badge->setText(QString("<span style='background:%1; color:white; padding:3px; font-weight:bold'>&nbsp;%2&nbsp;</span>"
                           " &nbsp;shortest: %3")
                       .arg(badgeColour(g), className(g.category), QString::fromUtf8(k::toString(g.shortest).data())));
  const QString relation = g.category == k::GrashofClass::ChangePoint ? "=" : (g.sPlusL < g.pPlusQ ? "<" : ">");
  m_sums->setText(QString("%1 %2 %3 %4").arg(g.sPlusL, 0, 'g', 6).arg(relation).arg(g.pPlusQ, 0, 'g', 6).arg(unit));
  const k::MobilityReport& m = a.mobility;
  m_mobility->setText(tr("M = 3(%1 − 1) − 2·%2 − %3 = %4").arg(m.links).arg(m.fullJoints).arg(m.halfJoints).arg(m.mobility));
  if (a.inputRange.fullRotation) {
    m_range->setText(tr("full turn"));
  } else {
    QStringList parts;
    for (const k::AngleRange& r : a.inputRange.ranges) parts << degrees(r.from, 1) + " … " + degrees(r.to, 1);
    m_range->setText(parts.join(", ") + tr(" (rocks between the ends)"));
  }
  if (a.transmission)
    m_transmissionRange->setText(tr("%1 … %2 (worst %3 from 90°)")
                                     .arg(degrees(a.transmission->minimum, 1), degrees(a.transmission->maximum, 1),
                                          degrees(a.transmission->worstDeviation, 1)));
  QStringList limits;
  for (const k::LimitPosition& p : a.limits.positions)
    limits << tr("θ₂ %1 → θ₄ %2").arg(degrees(p.crankAngle, 1), degrees(p.rockerAngle, 1));
  m_limits->setText(limits.isEmpty() ? tr("none") : limits.join("\n"));
  m_timeRatio->setText(a.limits.timeRatio ? tr("%1 (strokes %2 / %3)")
                                                .arg(*a.limits.timeRatio, 0, 'f', 4)
                                                .arg(degrees(*a.limits.slowStrokeCrankArc, 1), degrees(*a.limits.quickStrokeCrankArc, 1))
                                          : tr("—"));
}

void AnalysisPanel::refreshMotion() {
  const k::Pose& pose = m_document->pose();
  m_transmissionNow->setText(degrees(pose.transmissionAngle[k::fourbar::kC.index], 1));
  m_warning->setVisible(m_document->poseStatus() == k::PoseStatus::Singular);
  m_warning->setText(tr("Toggle position: coupler and rocker are in line; ω and α are undefined here."));
}

} // namespace linkwright::ui
