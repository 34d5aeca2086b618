#include "ui/plots/tolerance_window.h"

#include "ui/colors.h"
#include "ui/document/mechanism_document.h"
#include "ui/number_box.h"
#include "ui/number_text.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/plot_x_axis.h"

#include "kinematics/design/design.h"
#include "kinematics/tune/tolerance_dimensions.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHash>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr int kSettleMs = 300;

// `y` at the sweep's samples as runs, split where a value is not finite (never drawn).
SeriesRuns runsOf(const k::SweepResult& sweep, const XSource& x, const std::vector<double>& y) {
  SeriesRuns out;
  QList<QPointF> run;
  bool first = true;
  const auto close = [&] {
    if (!run.isEmpty()) out.runs.append(run);
    run.clear();
  };
  for (std::size_t j = 0; j < sweep.size() && j < y.size(); ++j) {
    if (!std::isfinite(y[j])) {
      close();
      continue;
    }
    run.append({sampleX(sweep, j, x, AngleUnit::Degrees), y[j]});
    out.minY = first ? y[j] : std::min(out.minY, y[j]);
    out.maxY = first ? y[j] : std::max(out.maxY, y[j]);
    first = false;
  }
  close();
  return out;
}

}  // namespace

ToleranceWindow::ToleranceWindow(MechanismDocument* document, QWidget* parent)
    : QWidget(parent, Qt::Window), m_document(document), m_tolerance(new NumberBox), m_samples(new QSpinBox),
      m_seed(new QSpinBox), m_own(new QTableWidget(0, 2)), m_output(new QComboBox), m_summary(new QLabel),
      m_band(new ForceChartView(tr("The band of the samples about the nominal"), false)),
      m_sensitivity(new ForceChartView(tr("Sensitivity to each dimension (exact)"), false)), m_busy(new QProgressBar),
      m_cancel(new QPushButton(tr("Cancel"))), m_run([this](const ToleranceOutcome& outcome) { display(outcome); }) {
  setWindowTitle(tr("Tolerances"));
  m_busy->setRange(0, 0);  // a study reports no fraction to the window: busy, not how far
  m_busy->setVisible(false);
  m_cancel->setVisible(false);
  m_cancel->setObjectName(QStringLiteral("toleranceCancel"));
  m_tolerance->setRange(0.0, 1e6);
  m_tolerance->setDecimals(4);
  m_tolerance->setValue(0.05);
  m_tolerance->setKeyboardTracking(false);
  m_samples->setRange(1, static_cast<int>(k::kMaxToleranceSamples));
  m_samples->setValue(1000);
  m_samples->setKeyboardTracking(false);
  m_seed->setRange(0, 1'000'000'000);
  m_seed->setValue(static_cast<int>(k::kDefaultToleranceSeed));
  m_seed->setKeyboardTracking(false);
  m_summary->setWordWrap(true);
  m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_summary->setObjectName(QStringLiteral("toleranceSummary"));
  auto* form = new QFormLayout;
  form->addRow(tr("± on every length and pivot"), m_tolerance);
  m_own->setHorizontalHeaderLabels({tr("Dimension"), tr("Its own ±")});
  m_own->horizontalHeader()->setStretchLastSection(true);
  m_own->verticalHeader()->hide();
  m_own->setMaximumHeight(150);
  m_own->setObjectName(QStringLiteral("ownTolerances"));
  form->addRow(tr("Its own ± (blank: the one above)"), m_own);
  form->addRow(tr("Monte-Carlo samples"), m_samples);
  form->addRow(tr("Seed"), m_seed);
  form->addRow(tr("Output"), m_output);
  auto* top = new QHBoxLayout;
  top->addLayout(form);
  auto* status = new QVBoxLayout;
  status->addWidget(m_summary, 1);
  auto* running = new QHBoxLayout;
  running->addWidget(m_busy, 1);
  running->addWidget(m_cancel);
  status->addLayout(running);
  top->addLayout(status, 1);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(m_band, 1);
  layout->addWidget(m_sensitivity, 1);
  resize(900, 760);

  m_settle.setSingleShot(true);
  m_settle.setInterval(kSettleMs);
  connect(&m_settle, &QTimer::timeout, this, &ToleranceWindow::refresh);
  connect(m_tolerance, &QDoubleSpinBox::valueChanged, this, &ToleranceWindow::scheduleRefresh);
  connect(m_samples, &QSpinBox::valueChanged, this, &ToleranceWindow::scheduleRefresh);
  connect(m_seed, &QSpinBox::valueChanged, this, &ToleranceWindow::scheduleRefresh);
  connect(m_own, &QTableWidget::cellChanged, this, [this] { scheduleRefresh(); });
  connect(m_output, &QComboBox::currentIndexChanged, this, [this] { redraw(); });
  connect(m_cancel, &QPushButton::clicked, this, [this] {
    m_run.cancel();
    display(ToleranceOutcome{.error = k::cancelledError()});
  });
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & Change::Design) scheduleRefresh();
  });
}

QString ToleranceWindow::summaryText() const { return m_summary->text(); }

void ToleranceWindow::showDimensions() {
  const std::vector<k::ToleranceDimension> dimensions = k::toleranceDimensions(m_document->design().mechanism);
  QStringList names;
  for (const k::ToleranceDimension& d : dimensions) names << QString::fromStdString(d.name);
  QStringList shown;
  for (int row = 0; row < m_own->rowCount(); ++row) shown << m_own->item(row, 0)->text();
  if (shown == names) return;
  QHash<QString, QString> typed;
  for (int row = 0; row < m_own->rowCount(); ++row)
    if (m_own->item(row, 1)) typed.insert(m_own->item(row, 0)->text(), m_own->item(row, 1)->text());
  const QSignalBlocker block(m_own);
  m_own->setRowCount(static_cast<int>(names.size()));
  for (int row = 0; row < names.size(); ++row) {
    auto* name = new QTableWidgetItem(names[row]);
    name->setFlags(name->flags() & ~Qt::ItemIsEditable);
    m_own->setItem(row, 0, name);
    m_own->setItem(row, 1, new QTableWidgetItem(typed.value(names[row])));
  }
}

void ToleranceWindow::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  refresh();
}

void ToleranceWindow::waitForStudy() { m_run.wait(); }

void ToleranceWindow::scheduleRefresh() {
  // What is shown belongs to the design it was computed for: drop it now, and the study under
  // way with it, and compute once settled.
  m_run.cancel();
  m_busy->setVisible(false);
  m_cancel->setVisible(false);
  m_monteCarlo.reset();
  m_sensitivities.reset();
  m_firstOrder.reset();
  m_summary->setText(tr("Computing for the design as it is now…"));
  redraw();
  if (isVisible()) m_settle.start();
}

void ToleranceWindow::refresh() {
  m_settle.stop();
  if (!isVisible()) return;
  const k::Design& design = m_document->design();
  const k::SweepSpec grid = k::designSweepSpec(design);
  k::MonteCarloSpec spec;
  spec.tolerance = m_tolerance->value();
  spec.samples = static_cast<std::size_t>(m_samples->value());
  spec.seed = static_cast<std::uint64_t>(m_seed->value());
  showDimensions();
  for (int row = 0; row < m_own->rowCount(); ++row) {
    const QString name = m_own->item(row, 0)->text();
    const QString typed = m_own->item(row, 1) ? m_own->item(row, 1)->text().trimmed() : QString();
    if (typed.isEmpty()) continue;
    bool ok = false;
    const double value = QLocale().toDouble(typed, &ok);
    if (!ok) {
      // A refused cell is named and nothing computed: what is drawn would not be what was typed.
      m_monteCarlo.reset();
      m_sensitivities.reset();
      m_firstOrder.reset();
      m_firstOrder.reset();
      m_firstOrder.reset();
      m_summary->setText(tr("No tolerance study: the ± of %1 must be a number (got '%2')").arg(name, typed));
      redraw();
      return;
    }
    spec.perDimension.push_back({name.toStdString(), value});
  }
  m_summary->setText(tr("Computing the study of %1 linkages…").arg(spec.samples));
  m_busy->setVisible(true);
  m_cancel->setVisible(true);
  m_run.start(toleranceJob(design, spec));
}

void ToleranceWindow::display(const ToleranceOutcome& outcome) {
  m_busy->setVisible(false);
  m_cancel->setVisible(false);
  if (outcome.error) {
    m_monteCarlo.reset();
    m_sensitivities.reset();
    m_firstOrder.reset();
    m_firstOrder.reset();
    m_summary->setText(outcome.error->code == k::ErrorCode::Cancelled
                           ? tr("The study was cancelled: change a field, or the design, to run it again.")
                           : tr("No tolerance study: %1").arg(QString::fromStdString(outcome.error->message)));
    m_output->clear();
    redraw();
    return;
  }
  m_monteCarlo = *outcome.band;
  m_sensitivities = *outcome.sensitivities;
  m_firstOrder = *outcome.summary;
  const QString kept = m_output->currentText();
  {
    const QSignalBlocker block(m_output);
    m_output->clear();
    for (const k::ToleranceBand& b : m_monteCarlo->bands) m_output->addItem(QString::fromStdString(b.column.name));
    // The output kept, or at first the last link's angle (a four-bar's rocker): the input's
    // own columns do not move with the dimensions.
    int found = m_output->findText(kept);
    for (int i = m_output->count() - 1; found < 0 && i >= 0; --i) {
      const QString name = m_output->itemText(i);
      if (name.endsWith(QStringLiteral("_angle_deg")) && !name.contains(QStringLiteral("transmission"))) found = i;
    }
    m_output->setCurrentIndex(std::max(found, 0));
  }
  redraw();
}

void ToleranceWindow::redraw() {
  const int chosen = m_output->currentIndex();
  const bool shown = m_monteCarlo && m_sensitivities && m_firstOrder && chosen >= 0 &&
                     static_cast<std::size_t>(chosen) < m_monteCarlo->bands.size();
  m_band->setVisible(shown);
  m_sensitivity->setVisible(shown);
  if (!shown) return;
  const k::ToleranceBand& band = m_monteCarlo->bands[static_cast<std::size_t>(chosen)];
  const k::SweepResult& nominal = m_monteCarlo->nominal;
  const k::Design& design = m_document->design();
  const PlotXAxis x = plotXAxis(design, nominal, PlotAxis::Input, AngleUnit::Degrees);
  const QString name = QString::fromStdString(band.column.name);
  const QString columnUnit = QString::fromStdString(k::columnUnit(band.column.quantity, design.mechanism.lengthUnit));
  // The band as its distance from the nominal, which a band a hundredth of the curve's size
  // can be seen by; beside it the first-order bound ±Σ|∂y/∂p|·tol.
  std::size_t column = 0;
  while (column < m_sensitivities->columns.size() && m_sensitivities->columns[column].name != band.column.name)
    ++column;
  const std::vector<double> tolerances = k::dimensionTolerances(m_monteCarlo->spec, m_monteCarlo->dimensions);
  std::vector<double> above(band.nominal.size()), below(band.nominal.size()), bound(band.nominal.size()),
      negative(band.nominal.size());
  for (std::size_t j = 0; j < band.nominal.size(); ++j) {
    above[j] = band.high[j] - band.nominal[j];
    below[j] = band.low[j] - band.nominal[j];
    bound[j] = column < m_sensitivities->columns.size() ? m_sensitivities->firstOrderDeviation(column, j, tolerances)
                                                        : std::numeric_limits<double>::quiet_NaN();
    negative[j] = -bound[j];
  }
  m_band->setCurves({{QStringLiteral("high"), tr("highest − nominal"), linkColor(2)},
                     {QStringLiteral("low"), tr("lowest − nominal"), linkColor(1)},
                     {QStringLiteral("bound"), tr("+ first-order worst case"), linkColor(0), Qt::DashLine},
                     {QStringLiteral("bound_low"), tr("− first-order worst case"), linkColor(0), Qt::DashLine}});
  m_band->setData({runsOf(nominal, x.source, above), runsOf(nominal, x.source, below), runsOf(nominal, x.source, bound),
                   runsOf(nominal, x.source, negative)},
                  tr("deviation [%1]").arg(columnUnit), x);
  // The output's name in the titles and its unit in the axes', which keep a unit whole when
  // they must shorten (fittedTitle).
  m_band->chart()->setTitle(tr("%1: the band of the samples about the nominal").arg(name));
  m_sensitivity->chart()->setTitle(tr("%1: its sensitivity to each dimension (exact)").arg(name));

  // The same column's derivatives, one curve per dimension.
  std::vector<ForceChartView::Curve> curves;
  std::vector<SeriesRuns> runs;
  const QString unit = QString::fromStdString(design.mechanism.lengthUnit);
  if (column < m_sensitivities->columns.size())
    for (std::size_t d = 0; d < m_sensitivities->dimensions.size(); ++d) {
      curves.push_back(
          {QStringLiteral("d%1").arg(d), QString::fromStdString(m_sensitivities->dimensions[d].name), linkColor(d)});
      runs.push_back(runsOf(m_sensitivities->sweep, x.source, m_sensitivities->derivative[column][d]));
    }
  m_sensitivity->setCurves(curves);
  m_sensitivity->setData(runs, tr("∂y/∂p [%1/%2]").arg(columnUnit, unit), x);

  const bool hasColumn = column < m_firstOrder->columns.size();
  const double firstOrder =
      hasColumn ? m_firstOrder->firstOrderWorst[column] : std::numeric_limits<double>::quiet_NaN();
  // The core's refined places are in the input's unit (degrees, a length); on a time base they
  // are instants, so the axis's input is read at the grid input nearest them.
  const auto place = [&](double refined, std::size_t gridSample) {
    return xReadoutText(nominal.time.empty() ? refined : sampleX(nominal, gridSample, x.source, AngleUnit::Degrees), x,
                        AngleUnit::Degrees);
  };
  m_summary->setText(
      tr("%1 at ±%2 %3 on %4 dimensions%12, %5 samples (seed %6): worst deviation %7 at %8; first-order worst "
         "case %9 at %13. %10 samples did not assemble on the grid and %11 met a toggle; they are not in the band.")
          .arg(name, numberText(m_monteCarlo->spec.tolerance, 'g', 4), unit)
          .arg(m_monteCarlo->dimensions.size())
          .arg(m_monteCarlo->used)
          .arg(m_monteCarlo->spec.seed)
          .arg(numberText(band.worstDeviation, 'g', 4), place(band.worstInput, band.worstGridSample),
               numberText(firstOrder, 'g', 4))
          .arg(m_monteCarlo->notAssembled)
          .arg(m_monteCarlo->singular)
          .arg(m_monteCarlo->spec.perDimension.empty()
                   ? QString()
                   : tr(" (%n with a ± of its own)", nullptr, static_cast<int>(m_monteCarlo->spec.perDimension.size())))
          .arg(hasColumn ? place(m_firstOrder->firstOrderWorstInput[column], m_firstOrder->firstOrderWorstAt[column])
                         : QStringLiteral("—")));
}

}  // namespace linkwright::ui
