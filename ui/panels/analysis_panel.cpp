#include "ui/panels/analysis_panel.h"

#include "ui/colors.h"
#include "ui/number_text.h"
#include "ui/readout_label.h"

#include "ui/document/design_templates.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"

#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QString degrees(double radians, int decimals = 2) { return numberText(k::radToDeg(radians), 'f', decimals) + "°"; }

QString className(k::GrashofClass c) {
  switch (c) {
  case k::GrashofClass::CrankRocker: return AnalysisPanel::tr("Crank-rocker");
  case k::GrashofClass::DoubleCrank: return AnalysisPanel::tr("Double-crank (drag link)");
  case k::GrashofClass::DoubleRocker: return AnalysisPanel::tr("Double-rocker");
  case k::GrashofClass::ChangePoint: return AnalysisPanel::tr("Change point");
  case k::GrashofClass::TripleRocker: return AnalysisPanel::tr("Triple-rocker (non-Grashof)");
  }
  return {};
}

QString badge(const QColor& colour, const QString& text, const QString& note) {
  return QString(
             "<span style='background:%1; color:white; padding:3px; font-weight:bold'>&nbsp;%2&nbsp;</span>"
             " &nbsp;%3")
      .arg(colour.name(), text.toHtmlEscaped(), note.toHtmlEscaped());
}

// An input value in the driver's display unit (model/driver.h): a crank's degrees, else the
// length unit.
QString inputText(const k::Mechanism& m, double q) {
  if (k::inputKind(m) == k::InputKind::Angle) return degrees(q, 1);
  return numberText(q, 'g', 6) + " " + QString::fromStdString(m.lengthUnit);
}

QString rangesText(const k::Mechanism& m, const std::vector<k::AngleRange>& ranges) {
  QStringList parts;
  for (const k::AngleRange& r : ranges)
    parts << (r.from == r.to ? inputText(m, r.from) : inputText(m, r.from) + " … " + inputText(m, r.to));
  return parts.join(", ");
}

}  // namespace

AnalysisPanel::AnalysisPanel(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_badge(new QLabel(this)), m_sums(new ReadoutLabel(this)),
      m_mobility(new QLabel(this)), m_range(new ReadoutLabel(this)), m_transmissionNow(new ReadoutLabel(this)),
      m_transmissionRange(new ReadoutLabel(this)), m_limits(new ReadoutLabel(this)),
      m_timeRatio(new ReadoutLabel(this)), m_stroke(new ReadoutLabel(this)), m_notAssembled(new ReadoutLabel(this)),
      m_warning(new QLabel(this)) {
  // Two columns over the canvas: the answers in sight at 1366×768 without scrolling. The
  // linkage's identity on the left, its motion's figures on the right; long values wrap.
  setObjectName("AnalysisStrip");
  // As tall as its wrapped rows, whatever the window's height: the canvas below gives way.
  setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Minimum);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(6, 2, 6, 2);
  m_badge->setTextFormat(Qt::RichText);
  m_badge->setWordWrap(true);
  m_mobility->setWordWrap(true);
  m_warning->setWordWrap(true);
  m_warning->setStyleSheet("color: #a15c00;");
  // A grid per column, not a QFormLayout: Qt 6.4's form kept a height of 0 for a row shown
  // again at a width it had laid out before (the thesis's rocker limits after a six-bar).
  m_left = addColumn(layout);
  m_right = addColumn(layout);
  m_left->addWidget(m_badge, 0, 0, 1, 2);
  addRow(m_left, tr("S + L, P + Q"), m_sums);
  addRow(m_left, tr("Mobility"), m_mobility);
  addRow(m_left, tr("Crank range"), m_range);
  addRow(m_left, tr("Not assembled"), m_notAssembled);
  addRow(m_left, tr("Transmission μ"), m_transmissionNow);
  addRow(m_right, tr("μ over cycle"), m_transmissionRange);
  addRow(m_right, tr("Rocker limits"), m_limits);
  addRow(m_right, tr("Time ratio"), m_timeRatio);
  addRow(m_right, tr("Ram stroke"), m_stroke);
  m_right->addWidget(m_warning, m_right->rowCount(), 0, 1, 2);
  for (QGridLayout* grid : {m_left, m_right}) grid->setRowStretch(grid->rowCount(), 1);  // rows at the top
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & (Changes(Change::Design) | Change::Analysis)) refreshDesign();  // a drag's grid landed
    refreshMotion();
  });
  refreshDesign();
  refreshMotion();
}

QString AnalysisPanel::grashofText() const { return m_badge->text(); }
QString AnalysisPanel::transmissionNowText() const { return m_transmissionNow->text(); }
QString AnalysisPanel::timeRatioText() const { return !m_timeRatio->isHidden() ? m_timeRatio->text() : QString(); }
QString AnalysisPanel::strokeText() const { return !m_stroke->isHidden() ? m_stroke->text() : QString(); }
QString AnalysisPanel::notAssembledText() const {
  return !m_notAssembled->isHidden() ? m_notAssembled->text() : QString();
}
QString AnalysisPanel::mobilityText() const { return m_mobility->text(); }

// Each column half the strip, whatever its values' one-line widths: a long badge or range
// wraps in its half rather than squeezing the other column into a sliver.
QGridLayout* AnalysisPanel::addColumn(QHBoxLayout* strip) {
  auto* column = new QWidget(this);
  column->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  auto* grid = new QGridLayout(column);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->setVerticalSpacing(1);
  grid->setColumnStretch(1, 1);
  strip->addWidget(column, 1);
  return grid;
}

void AnalysisPanel::addRow(QGridLayout* grid, const QString& name, QWidget* field) {
  auto* label = new QLabel(name, this);
  label->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  const int row = grid->rowCount();
  grid->addWidget(label, row, 0, Qt::AlignTop);
  grid->addWidget(field, row, 1);
  m_labels.insert(field, label);
}

// A hidden row's widgets are left out of the grid.
void AnalysisPanel::showRow(QWidget* field, bool shown) {
  field->setVisible(shown);
  m_labels.value(field)->setVisible(shown);
}

void AnalysisPanel::refreshDesign() {
  const k::DesignAnalysis& a = m_document->analysis();
  const k::MobilityReport& m = a.mobility;
  m_mobility->setText(
      tr("M = 3(%1 − 1) − 2·%2 − %3 = %4").arg(m.links).arg(m.fullJoints).arg(m.halfJoints).arg(m.mobility));
  const k::Mechanism& linkage = m_document->mechanism();
  const bool crank = k::inputKind(linkage) == k::InputKind::Angle;
  m_labels.value(m_range)->setText(crank ? tr("Crank range") : tr("Input range"));
  if (a.inputRange.fullRotation) m_range->setText(tr("full turn"));
  else
    m_range->setText(rangesText(linkage, a.inputRange.ranges) + (crank ? tr(" (rocks between the ends)") : QString()));
  // A four-bar's rows for any linkage that is one, however it was built or stored.
  const bool fourBar = a.grashof.has_value();
  showRow(m_sums, fourBar);
  for (QWidget* row : {m_transmissionRange, m_limits}) showRow(row, fourBar);
  if (fourBar) refreshFourBar();
  else refreshLinkage();
  // The columns ignore their one-line widths, but never get narrower than their labels and the
  // longest word of a value: the canvas column keeps room for the strip.
  for (QGridLayout* grid : {m_left, m_right}) grid->parentWidget()->setMinimumWidth(grid->minimumSize().width());
}

void AnalysisPanel::refreshFourBar() {
  const k::DesignAnalysis& a = m_document->analysis();
  const QString unit = QString::fromStdString(m_document->lengthUnit());
  const k::GrashofReport& g = *a.grashof;
  // Green for a Grashof linkage whose crank turns, amber for the rest.
  m_badge->setText(badge(g.inputFullyRotates ? colors().grashofCrankBadge : colors().grashofRockerBadge,
                         className(g.category),
                         tr("shortest: %1").arg(QString::fromUtf8(k::toString(g.shortest).data()))));
  const QString relation = g.category == k::GrashofClass::ChangePoint ? "=" : (g.sPlusL < g.pPlusQ ? "<" : ">");
  m_sums->setText(QString("%1 %2 %3 %4").arg(numberText(g.sPlusL), relation, numberText(g.pPlusQ), unit));
  if (a.transmission)
    m_transmissionRange->setText(tr("%1 … %2 (worst %3 from 90°)")
                                     .arg(degrees(a.transmission->minimum, 1), degrees(a.transmission->maximum, 1),
                                          degrees(a.transmission->worstDeviation, 1)));
  QStringList limits;
  for (const k::LimitPosition& p : a.limits.positions)
    limits << tr("θ₂ %1 → θ₄ %2").arg(degrees(p.crankAngle, 1), degrees(p.rockerAngle, 1));
  m_limits->setText(limits.isEmpty() ? tr("none") : limits.join("\n"));
  m_timeRatio->setText(
      a.limits.timeRatio ? tr("%1 (strokes %2 / %3)")
                               .arg(numberText(*a.limits.timeRatio, 'f', 4))
                               .arg(degrees(*a.limits.slowStrokeCrankArc, 1), degrees(*a.limits.quickStrokeCrankArc, 1))
                         : tr("—"));
  showRow(m_timeRatio, true);
  showRow(m_stroke, false);
  showRow(m_notAssembled, false);
}

void AnalysisPanel::refreshLinkage() {
  const k::DesignAnalysis& a = m_document->analysis();
  const QString unit = QString::fromStdString(m_document->lengthUnit());
  m_badge->setText(badge(colors().linkageBadge, kindDisplayName(m_document->design()),
                         tr("%1 points, %2 moving links")
                             .arg(m_document->mechanism().points.size())
                             .arg(m_document->mechanism().links.size())));
  const auto& q = a.quickReturn;
  showRow(m_timeRatio, q.has_value());
  showRow(m_stroke, q.has_value());
  if (q) {
    m_timeRatio->setText(tr("%1 (strokes %2 / %3)")
                             .arg(numberText(q->timeRatio, 'f', 4))
                             .arg(degrees(q->slowStrokeCrankArc, 1), degrees(q->quickStrokeCrankArc, 1)));
    m_stroke->setText(QString("%1 %2").arg(numberText(q->stroke, 'f', 2), unit));
  }
  const auto& gaps = a.notAssembled;
  showRow(m_notAssembled, !gaps.empty());
  m_notAssembled->setText(rangesText(m_document->mechanism(), gaps));
}

void AnalysisPanel::refreshMotion() {
  const k::Pose& pose = m_document->pose();
  const k::Mechanism& m = m_document->mechanism();
  if (const auto& fourBar = m_document->fourBar()) {
    m_transmissionNow->setText(degrees(pose.transmissionAngle[fourBar->c.index], 1));
  } else {
    // One angle per dyad that has one (RRR, RRP and actuator joints), named by its joint.
    QStringList parts;
    for (const std::size_t i : k::transmissionJoints(m))
      if (i < pose.transmissionAngle.size())
        parts << QString("%1 %2").arg(QString::fromStdString(m.points[i].name), degrees(pose.transmissionAngle[i], 1));
    m_transmissionNow->setText(parts.isEmpty() ? tr("—") : parts.join(", "));
  }
  m_warning->setVisible(m_document->poseStatus() == k::PoseStatus::Singular);
  m_warning->setText(m_document->fourBar()
                         ? tr("Toggle position: coupler and rocker are in line; ω and α are undefined here.")
                         : tr("Toggle position: a dyad is stretched straight or folded; ω and α are undefined here."));
}

}  // namespace linkwright::ui
