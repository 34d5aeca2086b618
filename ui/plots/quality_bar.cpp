#include "ui/plots/quality_bar.h"

#include "ui/number_text.h"
#include "ui/readout_label.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"

#include <QComboBox>
#include <QEvent>
#include <QFontMetrics>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <cmath>

namespace linkwright::ui {
namespace {

QString superscript(int n) {
  static const QString digits = QStringLiteral("⁰¹²³⁴⁵⁶⁷⁸⁹");
  QString s = n < 0 ? QStringLiteral("⁻") : QString();
  for (const QChar c : QString::number(std::abs(n))) s += digits[c.digitValue()];
  return s;
}

// What the measurement means, and the seeds' table (docs/accuracy.md) for scale.
QString boxToolTip() {
  return QualityBar::tr(
      "<p>How many samples the plots get per pixel of their width, and how tightly Newton solves free "
      "points:</p><ul><li><b>Draft</b>: 1 sample per 4 px (≥ 36 per revolution), tolerance 10⁻⁶</li>"
      "<li><b>Normal</b>: 1 per px (≥ 360 per revolution), tolerance 10⁻¹⁰</li>"
      "<li><b>Precise</b>: 4 per px (≥ 3600 per revolution), tolerance 10⁻¹²</li></ul>"
      "<p>Peaks read off N samples per revolution err by about (360°/N)². The worst peak error on "
      "miranda-fourbar and shaper (docs/accuracy.md): 18–33 % at N = 12, 1.8–5.2 % at 36, 0.013–0.041 % "
      "at 360, 2.3–3.6 × 10⁻⁶ at 3600. The error shown beside is measured on this design.</p>"
      "<p>The analysis panel's limits, the CSV export and <i>linkwright-cli extremes</i> do not depend "
      "on this setting.</p>");
}

}  // namespace

QualityBar::QualityBar(MechanismDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_box(new QComboBox(this)), m_cost(new ReadoutLabel(this)),
      m_error(new QLabel(this)) {
  // The box, then what it costs over what it buys, one line each, beside it.
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(4, 2, 4, 2);
  row->setSpacing(6);
  auto* label = new QLabel(tr("Plot &quality:"), this);
  m_box->setObjectName(QStringLiteral("quality"));
  m_box->addItems({tr("Draft"), tr("Normal"), tr("Precise")});
  m_box->setToolTip(boxToolTip());
  m_box->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  label->setBuddy(m_box);
  row->addWidget(label);
  row->addWidget(m_box);
  row->addSpacing(6);
  auto* figures = new QVBoxLayout;
  figures->setSpacing(0);
  m_cost->setObjectName(QStringLiteral("qualityCost"));
  m_error->setObjectName(QStringLiteral("qualityError"));
  // A rocking crank's reason is a sentence: it wraps rather than widening the plots.
  m_error->setWordWrap(true);
  reserveErrorLines();
  figures->addWidget(m_cost);
  figures->addWidget(m_error);
  row->addLayout(figures, 1);

  connect(m_box, &QComboBox::currentIndexChanged, this, [this](int index) {
    const auto quality = static_cast<SamplingQuality>(index);
    m_document->setQuality(quality);
    emit qualityChosen(quality);
  });
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & (Changes(Change::Design) | Change::Request)) refreshCost();
    if (what & (Changes(Change::Design) | Change::Request | Change::Estimate)) refreshError();
  });
  refreshCost();
  refreshError();
}

void QualityBar::reserveErrorLines() {
  // Two lines, whether the figure or the sentence shows: the bar keeps its height when a drag
  // crosses into a rocking crank, so the charts below are neither resized nor laid out again.
  m_error->setMinimumHeight(2 * QFontMetrics(m_error->font()).lineSpacing());
}

void QualityBar::changeEvent(QEvent* event) {
  QWidget::changeEvent(event);
  if (event->type() == QEvent::FontChange) reserveErrorLines();
}

QString QualityBar::costText() const { return m_cost->text(); }
QString QualityBar::errorText() const { return m_error->text(); }

QString QualityBar::formatRelative(double error) {
  if (!std::isfinite(error)) return QStringLiteral("—");
  if (error < 1e-15) return QStringLiteral("< 10") + superscript(-15);
  const int exponent = static_cast<int>(std::floor(std::log10(error)));
  const double mantissa = error / std::pow(10.0, exponent);
  // 9.96 would print as 10.0: carry it into the exponent instead.
  if (std::lround(mantissa * 10.0) >= 100) return QStringLiteral("1.0 × 10") + superscript(exponent + 1);
  return QString::number(mantissa, 'f', 1) + QStringLiteral(" × 10") + superscript(exponent);
}

void QualityBar::refreshCost() {
  {
    const QSignalBlocker block(m_box);
    m_box->setCurrentIndex(static_cast<int>(m_document->quality()));
  }
  const kinematics::SweepSpec& spec = m_document->displaySpec();
  const double spanDeg = kinematics::radToDeg(spec.toAngle - spec.fromAngle);
  const int msDecimals = m_document->sweepMilliseconds() < 10.0 ? 2 : 1;
  // On a time base the samples are evenly spaced in time, not in crank angle.
  if (spec.time)
    m_cost->setText(tr("%1 samples over %2 s · sweep %3 ms")
                        .arg(spec.samples)
                        .arg(numberText(spec.time->toTime - spec.time->fromTime, 'g', 4))
                        .arg(m_document->sweepMilliseconds(), 0, 'f', msDecimals));
  else if (kinematics::inputKind(m_document->mechanism()) == kinematics::InputKind::Length)
    m_cost->setText(tr("%1 samples over %2 %3 · sweep %4 ms")
                        .arg(spec.samples)
                        .arg(numberText(spec.toAngle - spec.fromAngle, 'g', 4))
                        .arg(QString::fromStdString(m_document->mechanism().lengthUnit))
                        .arg(m_document->sweepMilliseconds(), 0, 'f', msDecimals));
  else
    m_cost->setText(tr("%1 samples/rev · sweep %2 ms")
                        .arg(samplesPerRevolution(spec.samples, spanDeg))
                        .arg(m_document->sweepMilliseconds(), 0, 'f', msDecimals));
  m_cost->setToolTip(tr("%1 samples across the plots, computing %2; the last sweep took %3 ms")
                         .arg(spec.samples)
                         .arg(m_document->request().accelerations ? tr("positions, ω and α")
                              : m_document->request().velocities  ? tr("positions and ω")
                                                                  : tr("positions only"))
                         .arg(m_document->sweepMilliseconds(), 0, 'f', 3));
}

void QualityBar::refreshError() {
  const QualityEstimate& e = m_document->qualityEstimate();
  // Until the estimate settles (a drag, a resize), the last figure stays, greyed.
  m_error->setEnabled(!m_document->qualityEstimatePending());
  if (!e.error) {
    m_error->setText(e.samplesPerRevolution == 0 && e.unavailable.isEmpty() ? tr("peak error: measuring…")
                                                                            : tr("peak error %1").arg(e.unavailable));
    m_error->setToolTip(e.detail.isEmpty() ? QString()
                                           : tr("<p>The error is measured against the exact peaks over one full cycle "
                                                "of the crank. The core says: %1</p>")
                                                 .arg(e.detail.toHtmlEscaped()));
    return;
  }
  const kinematics::PeakError& p = *e.error;
  m_error->setText(tr("worst peak error %1").arg(formatRelative(p.worstRate())));
  m_error->setToolTip(
      tr("<p>Worst relative error of the peaks read off %1 samples per revolution against the exact "
         "peaks (refined between samples), measured on this design in %2 ms:</p>"
         "<table><tr><td>|ω| of links</td><td>%3</td></tr><tr><td>|α| of links</td><td>%4</td></tr>"
         "<tr><td>speed of points</td><td>%5</td></tr><tr><td>acceleration of points</td><td>%6</td></tr>"
         "<tr><td>extreme angles</td><td>%7°</td></tr></table>"
         "<p>Crank at constant speed (α₂ = 0).</p>")
          .arg(e.samplesPerRevolution)
          .arg(numberText(e.measureMilliseconds, 'f', 1))
          .arg(formatRelative(p.omega), formatRelative(p.alpha), formatRelative(p.speed),
               formatRelative(p.acceleration))
          .arg(kinematics::radToDeg(p.angle), 0, 'g', 2));
}

}  // namespace linkwright::ui
