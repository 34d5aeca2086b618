#include "ui/plots/optimise_window.h"

#include "ui/colors.h"
#include "ui/document/mechanism_document.h"
#include "ui/number_box.h"
#include "ui/number_text.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/optimise_runner.h"
#include "ui/plots/plot_x_axis.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <variant>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

// The objective's value as shown: μ in degrees, the others in their unit.
double shownValue(k::ObjectiveKind kind, double value) {
  return kind == k::ObjectiveKind::Transmission ? k::radToDeg(value) : value;
}

QString unitOf(k::ObjectiveKind kind, const k::Design& design) {
  switch (kind) {
  case k::ObjectiveKind::PeakAlpha: return QObject::tr("rad/s²");
  case k::ObjectiveKind::Transmission: return QObject::tr("°");
  case k::ObjectiveKind::Path: return QString::fromStdString(design.mechanism.lengthUnit);
  case k::ObjectiveKind::RmsTorque: return QObject::tr("N·m");
  }
  return {};
}

// The chart's value axis: the quantity at each sample, whose peak or worst is the objective.
QString curveTitle(const k::OptimiseObjective& o, const QString& unit, const QString& lengthUnit) {
  switch (o.kind) {
  case k::ObjectiveKind::PeakAlpha: return QObject::tr("α of %1 [%2]").arg(QString::fromStdString(o.link), unit);
  case k::ObjectiveKind::Transmission: return QObject::tr("worst transmission angle min(μ, 180° − μ) [%1]").arg(unit);
  case k::ObjectiveKind::Path: return QObject::tr("y [%1]").arg(lengthUnit);
  case k::ObjectiveKind::RmsTorque: return QObject::tr("driving torque [%1]").arg(unit);
  }
  return {};
}

// A curve as one run of points, x and y scaled for display, non-finite values left out.
SeriesRuns runOf(const std::vector<double>& x, const std::vector<double>& y, double xScale, double yScale) {
  SeriesRuns out;
  QList<QPointF> run;
  for (std::size_t j = 0; j < x.size() && j < y.size(); ++j) {
    const double px = x[j] * xScale, py = y[j] * yScale;
    if (!std::isfinite(px) || !std::isfinite(py)) continue;
    out.minY = run.isEmpty() ? py : std::min(out.minY, py);
    out.maxY = run.isEmpty() ? py : std::max(out.maxY, py);
    run.append({px, py});
  }
  if (!run.isEmpty()) out.runs.append(run);
  return out;
}

// Each target drawn as a cross, two strokes a target, `dx` and `dy` its half sizes along the
// axes (the chart's x and y scales differ).
SeriesRuns crossesAt(const std::vector<Eigen::Vector2d>& targets, double dx, double dy) {
  SeriesRuns out;
  bool first = true;
  for (const Eigen::Vector2d& t : targets) {
    out.runs.append(QList<QPointF>{QPointF(t.x() - dx, t.y() - dy), QPointF(t.x() + dx, t.y() + dy)});
    out.runs.append(QList<QPointF>{QPointF(t.x() - dx, t.y() + dy), QPointF(t.x() + dx, t.y() - dy)});
    out.minY = first ? t.y() - dy : std::min(out.minY, t.y() - dy);
    out.maxY = first ? t.y() + dy : std::max(out.maxY, t.y() + dy);
    first = false;
  }
  return out;
}

}  // namespace

OptimiseWindow::OptimiseWindow(MechanismDocument* document, QWidget* parent)
    : QWidget(parent, Qt::Window), m_document(document), m_runner(new OptimiseRunner(this)), m_objective(new QComboBox),
      m_link(new QComboBox), m_point(new QComboBox), m_measure(new QComboBox), m_targets(new QLineEdit),
      m_range(new NumberBox), m_pivots(new QListWidget), m_seed(new QSpinBox), m_evaluations(new QSpinBox),
      m_run(new QPushButton(tr("&Run"))), m_cancel(new QPushButton(tr("&Cancel"))),
      m_accept(new QPushButton(tr("&Accept"))), m_discard(new QPushButton(tr("&Discard"))),
      m_progress(new QProgressBar), m_summary(new QLabel),
      m_chart(new ForceChartView(tr("The objective over the cycle: before (dashed) and after"), false)) {
  setWindowTitle(tr("Optimise"));
  m_objective->addItem(tr("Peak |α| of a link (lower)"), static_cast<int>(k::ObjectiveKind::PeakAlpha));
  m_objective->addItem(tr("Worst transmission angle (higher)"), static_cast<int>(k::ObjectiveKind::Transmission));
  m_objective->addItem(tr("Distance of a point's path from targets (lower)"), static_cast<int>(k::ObjectiveKind::Path));
  m_objective->addItem(tr("RMS driving torque (lower; needs masses)"), static_cast<int>(k::ObjectiveKind::RmsTorque));
  m_measure->addItem(tr("worst target"));
  m_measure->addItem(tr("RMS of the targets"));
  m_targets->setPlaceholderText(tr("x, y; x, y; …"));
  m_range->setRange(1.0, 95.0);
  m_range->setDecimals(0);
  m_range->setSuffix(tr(" %"));
  m_range->setValue(k::kDefaultLengthRange * 100.0);
  m_pivots->setMaximumHeight(56);
  m_seed->setRange(0, 1'000'000'000);
  m_seed->setValue(static_cast<int>(k::kDefaultOptimiseSeed));
  m_evaluations->setRange(10, 100000);
  m_evaluations->setValue(k::kDefaultOptimiseEvaluations);
  m_summary->setWordWrap(true);
  m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
  m_summary->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  m_summary->setObjectName(QStringLiteral("optimiseSummary"));
  m_summary->setMinimumWidth(360);

  auto* form = new QFormLayout;
  form->addRow(tr("Objective"), m_objective);
  form->addRow(tr("Link"), m_link);
  form->addRow(tr("Point"), m_point);
  form->addRow(tr("Targets (%1)").arg(QString::fromStdString(document->design().mechanism.lengthUnit)), m_targets);
  form->addRow(tr("Distance"), m_measure);
  form->addRow(tr("± on each length"), m_range);
  form->addRow(tr("Pivots kept"), m_pivots);
  form->addRow(tr("Seed"), m_seed);
  form->addRow(tr("Designs to measure"), m_evaluations);
  auto* runRow = new QHBoxLayout;
  runRow->addWidget(m_run);
  runRow->addWidget(m_cancel);
  runRow->addWidget(m_progress, 1);
  auto* resultRow = new QHBoxLayout;
  resultRow->addStretch(1);
  resultRow->addWidget(m_discard);
  resultRow->addWidget(m_accept);
  auto* left = new QVBoxLayout;
  left->addLayout(form);
  left->addLayout(runRow);
  auto* top = new QHBoxLayout;
  top->addLayout(left);
  top->addWidget(m_summary, 1);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(top);
  layout->addWidget(m_chart, 1);
  layout->addLayout(resultRow);
  resize(960, 760);
  // A hidden chart keeps its place: the form and Run/Cancel stay where they were while it runs.
  QSizePolicy chartPolicy = m_chart->sizePolicy();
  chartPolicy.setRetainSizeWhenHidden(true);
  m_chart->setSizePolicy(chartPolicy);

  connect(m_run, &QPushButton::clicked, this, &OptimiseWindow::run);
  connect(m_cancel, &QPushButton::clicked, this, &OptimiseWindow::cancelRun);
  connect(m_accept, &QPushButton::clicked, this, &OptimiseWindow::acceptResult);
  connect(m_discard, &QPushButton::clicked, this, &OptimiseWindow::discardResult);
  connect(m_objective, &QComboBox::currentIndexChanged, this, &OptimiseWindow::updateFields);
  connect(m_runner, &OptimiseRunner::progressed, this, [this](int done, int total) {
    m_progress->setRange(0, total);
    m_progress->setValue(std::min(done, total));
  });
  connect(m_runner, &OptimiseRunner::finished, this, &OptimiseWindow::onFinished);
  connect(m_runner, &OptimiseRunner::droppedEnded, this, &OptimiseWindow::updateFields);
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & Change::Design) followDesign();
  });
  followDesign();
  m_summary->setText(tr("Choose what to improve and press Run. The design changes only when you Accept."));
}

OptimiseWindow::~OptimiseWindow() = default;

QString OptimiseWindow::summaryText() const { return m_summary->text(); }

bool OptimiseWindow::running() const { return m_runner->running(); }

k::Result<k::OptimiseRequest> OptimiseWindow::request() const {
  k::OptimiseRequest r;
  r.objective.kind = static_cast<k::ObjectiveKind>(m_objective->currentData().toInt());
  r.objective.link = m_link->currentText().toStdString();
  r.objective.point = m_point->currentText().toStdString();
  r.objective.measure = m_measure->currentIndex() == 1 ? k::PathMeasure::Rms : k::PathMeasure::Worst;
  if (r.objective.kind == k::ObjectiveKind::Path) {
    const QStringList pairs = m_targets->text().split(QLatin1Char(';'), Qt::SkipEmptyParts);
    for (const QString& pair : pairs) {
      const QStringList xy = pair.split(QLatin1Char(','));
      bool okX = false, okY = false;
      const double x = xy.size() == 2 ? xy[0].trimmed().toDouble(&okX) : 0.0;
      const double y = xy.size() == 2 ? xy[1].trimmed().toDouble(&okY) : 0.0;
      if (!okX || !okY)
        return k::Error{
            k::ErrorCode::InvalidValue, "targets",
            tr("Targets: '%1' is not a point x, y (points are separated by ';')").arg(pair.trimmed()).toStdString()};
      r.objective.targets.emplace_back(x, y);
    }
  }
  r.constraints.lengthRange = m_range->value() / 100.0;
  r.constraints.fixedPivots.emplace();
  for (int i = 0; i < m_pivots->count(); ++i)
    if (m_pivots->item(i)->checkState() == Qt::Checked)
      r.constraints.fixedPivots->push_back(m_pivots->item(i)->text().toStdString());
  r.options.seed = static_cast<std::uint32_t>(m_seed->value());
  r.options.evaluations = m_evaluations->value();
  return r;
}

void OptimiseWindow::updateFields() {
  const auto kind = static_cast<k::ObjectiveKind>(m_objective->currentData().toInt());
  m_link->setEnabled(kind == k::ObjectiveKind::PeakAlpha);
  for (QWidget* w :
       {static_cast<QWidget*>(m_point), static_cast<QWidget*>(m_targets), static_cast<QWidget*>(m_measure)})
    w->setEnabled(kind == k::ObjectiveKind::Path);
  const bool busy = m_runner->running();
  m_run->setEnabled(!busy);
  m_cancel->setEnabled(busy);
  m_accept->setEnabled(!busy && m_result && m_result->improved);
  m_discard->setEnabled(!busy && m_result.has_value());
}

void OptimiseWindow::followDesign() {
  const k::Mechanism& m = m_document->design().mechanism;
  // The lists follow the linkage, keeping what was chosen where it still exists.
  const QString link = m_link->currentText(), point = m_point->currentText();
  QStringList kept;
  for (int i = 0; i < m_pivots->count(); ++i)
    if (m_pivots->item(i)->checkState() == Qt::Checked) kept << m_pivots->item(i)->text();
  const bool first = m_pivots->count() == 0 && m_link->count() == 0;
  m_link->clear();
  m_point->clear();
  m_pivots->clear();
  for (const k::Link& l : m.links) m_link->addItem(QString::fromStdString(l.name));
  for (const k::Point& p : m.points) {
    m_point->addItem(QString::fromStdString(p.name));
    if (!std::holds_alternative<k::GroundPoint>(p.definition)) continue;
    auto* item = new QListWidgetItem(QString::fromStdString(p.name), m_pivots);
    item->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
    item->setCheckState(first || kept.contains(item->text()) ? Qt::Checked : Qt::Unchecked);
  }
  // A first look at a linkage offers its last link (a four-bar's rocker) and its coupler point.
  m_link->setCurrentIndex(m_link->findText(link) >= 0 ? m_link->findText(link) : m_link->count() - 1);
  m_point->setCurrentIndex(m_point->findText(point) >= 0 ? m_point->findText(point) : m_point->count() - 1);
  if (!m_applying && m_applied) {
    // Ctrl+Z, or any later edit: the summary and the chart told of the design applied then.
    m_applied = false;
    m_chart->setVisible(false);
    m_summary->setText(
        tr("The design changed after the optimised one was applied (Ctrl+Z or another edit): "
           "what was shown is gone. Run again for the design as it is now."));
  }
  if (!m_applying && (m_result || m_runner->running())) {
    // What is shown was computed for the design before this edit.
    const bool wasRunning = m_runner->running();
    m_runner->drop();
    m_result.reset();
    m_chart->setVisible(false);
    m_summary->setText(wasRunning ? tr("The design changed while optimising: the run was stopped. Run again for "
                                       "the design as it is now.")
                                  : tr("The design changed: the result computed for the design before was "
                                       "dropped. Run again for the design as it is now."));
  }
  updateFields();
}

void OptimiseWindow::run() {
  const auto r = request();
  if (!r) {
    m_summary->setText(QString::fromStdString(r.error().message));
    return;
  }
  m_result.reset();
  m_applied = false;
  m_chart->setVisible(false);
  m_summary->setText(tr("Optimising…"));
  m_runner->start(m_document->design(), *r);
  updateFields();
}

void OptimiseWindow::cancelRun() {
  m_runner->cancel();
  m_summary->setText(tr("Cancelling: the best design found so far will be shown."));
}

void OptimiseWindow::onFinished() {
  const auto& outcome = m_runner->outcome();
  // A run whose simplexes shrank before the budget was spent has ended all the same; a
  // cancelled one keeps the share it reached.
  if (outcome && outcome->ok() && !outcome->value().cancelled) m_progress->setValue(m_progress->maximum());
  if (!outcome || !outcome->ok()) {
    m_summary->setText(tr("No optimisation: %1")
                           .arg(outcome ? QString::fromStdString(outcome->error().message) : tr("it was stopped")));
    updateFields();
    emit runEnded();
    return;
  }
  m_result = outcome->value();
  showResult();
  updateFields();
  emit runEnded();
}

void OptimiseWindow::showResult() {
  const k::LinkageOptimisation& r = *m_result;
  const k::Design& design = m_document->design();
  const k::ObjectiveKind kind = r.objective.kind;
  const QString unit = unitOf(kind, design);
  const double before = shownValue(kind, r.before), after = shownValue(kind, r.after);
  QString text = tr("<b>%1</b>: %2 → <b>%3</b> %4")
                     .arg(QString::fromStdString(k::objectiveName(r.objective)).toHtmlEscaped(),
                          numberText(before, 'g', 5), numberText(after, 'g', 5), unit);
  if (before != 0.0)
    text += tr(" (%1%2 %)")
                .arg(after >= before ? QStringLiteral("+") : QStringLiteral("−"))
                .arg(numberText(std::abs(after / before - 1.0) * 100.0, 'g', 3));
  text += tr("<br>%1 designs measured, %2 keeping every constraint, seed %3%4.")
              .arg(r.evaluations)
              .arg(r.feasibleEvaluations)
              .arg(m_seed->value())
              .arg(r.cancelled ? tr(" (cancelled: the best found before)") : QString());
  if (!r.improved) text += tr("<br>Nothing better was found within the ranges: the design stays as it is.");
  const auto& c = r.constraints;
  text += tr("<br>Kept: %1branch, assembly over the whole grid, ranges, fixed pivots.")
              .arg(c.grashofAfter ? tr("Grashof class %1, ").arg(QString::fromUtf8(k::toString(*c.grashofAfter).data()))
                                  : QString());
  QStringList changed;
  const QString lengthUnit = QString::fromStdString(design.mechanism.lengthUnit);
  for (std::size_t d = 0; d < r.dimensions.size(); ++d)
    if (r.values[d] != r.dimensions[d].dimension.value)
      changed << tr("%1 %2 → %3")
                     .arg(QString::fromStdString(r.dimensions[d].dimension.name).toHtmlEscaped(),
                          numberText(r.dimensions[d].dimension.value, 'g', 5), numberText(r.values[d], 'g', 5));
  if (!changed.isEmpty()) text += tr("<br>Changed (%1): %2.").arg(lengthUnit, changed.join(QStringLiteral("; ")));
  m_summary->setText(text);

  // The curves: a path in the plane with its targets, else the quantity against the input.
  const bool path = kind == k::ObjectiveKind::Path;
  const bool angle = !design.time && k::inputKind(design.mechanism) == k::InputKind::Angle;
  const double xScale = path || !angle ? 1.0 : 180.0 / k::kPi;
  const double yScale = kind == k::ObjectiveKind::Transmission ? 180.0 / k::kPi : 1.0;
  std::vector<ForceChartView::Curve> curves{{QStringLiteral("before"), tr("before"), linkColor(0), Qt::DashLine},
                                            {QStringLiteral("after"), tr("after"), linkColor(2)}};
  std::vector<SeriesRuns> runs{runOf(r.curveBefore.x, r.curveBefore.y, xScale, yScale),
                               runOf(r.curveAfter.x, r.curveAfter.y, xScale, yScale)};
  double lo = 0.0, hi = 0.0;
  bool first = true;
  for (const auto* curve : {&r.curveBefore, &r.curveAfter})
    for (const double x : curve->x) {
      lo = first ? x * xScale : std::min(lo, x * xScale);
      hi = first ? x * xScale : std::max(hi, x * xScale);
      first = false;
    }
  if (path) {
    curves.push_back({QStringLiteral("targets"), tr("targets"), linkColor(1)});
    const double ySpan = std::max(std::max(runs[0].maxY, runs[1].maxY) - std::min(runs[0].minY, runs[1].minY), 1e-9);
    runs.push_back(crossesAt(r.objective.targets, 0.015 * std::max(hi - lo, 1e-9), 0.025 * ySpan));
    for (const Eigen::Vector2d& t : r.objective.targets) {
      lo = std::min(lo, t.x());
      hi = std::max(hi, t.x());
    }
  }
  PlotXAxis x;
  x.title = path          ? tr("x [%1]").arg(lengthUnit)
            : design.time ? timeAxisTitle()
                          : inputAxisTitle(design.mechanism, AngleUnit::Degrees);
  x.inputName = inputDisplayName(design.mechanism);
  x.range = exactAxisRange(lo, hi);
  const QString value = curveTitle(r.objective, unit, lengthUnit);
  m_chart->setCurves(curves);
  m_chart->setData(runs, value, x);
  m_chart->setVisible(true);
}

void OptimiseWindow::acceptResult() {
  if (!m_result || !m_result->improved) return;
  m_applying = true;
  const auto why = m_document->edit(
      m_result->design, tr("Optimise the %1").arg(QString::fromStdString(k::objectiveName(m_result->objective))));
  m_applying = false;
  if (why) {
    m_summary->setText(tr("Not applied: %1").arg(*why));
    return;
  }
  m_result.reset();
  m_applied = true;
  m_summary->setText(m_summary->text() + tr("<br><b>Applied</b> as one edit (Ctrl+Z undoes it)."));
  updateFields();
}

void OptimiseWindow::discardResult() {
  m_result.reset();
  m_chart->setVisible(false);
  m_summary->setText(tr("Discarded: the design is as it was."));
  updateFields();
}

}  // namespace linkwright::ui
