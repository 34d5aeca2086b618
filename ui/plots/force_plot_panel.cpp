#include "ui/plots/force_plot_panel.h"

#include "ui/colors.h"
#include "ui/document/force_results.h"
#include "ui/document/mechanism_document.h"
#include "ui/number_text.h"
#include "ui/plots/axis_range.h"
#include "ui/plots/chart_colors.h"
#include "ui/plots/chart_scale.h"
#include "ui/plots/crank_angle_chart.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/machine_page.h"
#include "ui/plots/plot_area_alignment.h"
#include "ui/plots/plot_panel.h"
#include "ui/plots/plot_x_axis.h"
#include "ui/plots/polar_load_view.h"

#include <QChart>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QTabWidget>
#include <QVBoxLayout>

#include <utility>

namespace linkwright::ui {

namespace k = kinematics;

namespace {
constexpr int kChartMinimumHeight = 200;
constexpr int kPolarMinimumWidth = 260;
}  // namespace

ForcePlotPanel::ForcePlotPanel(MechanismDocument* document, ForceResults* forces, QWidget* parent)
    : QWidget(parent), m_document(document), m_forces(forces), m_status(new QLabel(this)),
      m_torque(new ForceChartView(tr("Driving torque"), false)), m_joints(new ForceChartView(tr("Joint forces"), true)),
      m_shaking(new ForceChartView(tr("Shaking force on the frame"), false)),
      m_shakingMoment(new ForceChartView(tr("Shaking moment"), false)), m_shakingPeaks(new QLabel),
      m_pages(new QTabWidget), m_selector(new QComboBox), m_polar(new PolarLoadView),
      m_machine(new MachinePage(document)), m_charts(new QWidget(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  m_settleTimer.setSingleShot(true);
  m_settleTimer.setInterval(PlotPanel::kDataSettleMs);
  connect(&m_settleTimer, &QTimer::timeout, this, &ForcePlotPanel::settleValueRanges);
  m_status->setWordWrap(true);
  m_status->setAlignment(Qt::AlignCenter);
  m_status->setObjectName(QStringLiteral("forceStatus"));
  layout->addWidget(m_status);

  // Two pages, each with the pane's full width: the curves against crank angle, and the polar
  // diagrams (side by side they were too narrow to read in the default window).
  QTabWidget* pages = m_pages;
  pages->setDocumentMode(true);
  auto* chartsLayout = new QVBoxLayout(m_charts);
  chartsLayout->setContentsMargins(0, 0, 0, 0);
  chartsLayout->addWidget(pages);
  auto* curves = new QWidget;
  auto* left = new QVBoxLayout(curves);
  left->setContentsMargins(0, 0, 0, 0);
  m_torque->setMinimumHeight(kChartMinimumHeight);
  m_joints->setMinimumHeight(kChartMinimumHeight);
  left->addWidget(m_torque, 1);
  left->addWidget(m_joints, 1);
  auto* polar = new QWidget;
  auto* right = new QVBoxLayout(polar);
  right->setContentsMargins(0, 0, 0, 0);
  auto* selectorRow = new QHBoxLayout;
  auto* selectorLabel = new QLabel(tr("Polar diagram of"));
  selectorLabel->setBuddy(m_selector);
  selectorRow->addWidget(selectorLabel);
  selectorRow->addWidget(m_selector, 1);
  right->addLayout(selectorRow);
  m_polar->setMinimumWidth(kPolarMinimumWidth);
  right->addWidget(m_polar, 1);
  // The frame's share: what the linkage shakes its mounting with (the forces the moving bodies
  // exert on the ground, and their moment about the first ground pivot).
  auto* shaking = new QWidget;
  auto* frame = new QVBoxLayout(shaking);
  frame->setContentsMargins(0, 0, 0, 0);
  m_shaking->setMinimumHeight(kChartMinimumHeight);
  m_shakingMoment->setMinimumHeight(kChartMinimumHeight);
  m_shakingPeaks->setObjectName(QStringLiteral("shakingPeaks"));
  m_shakingPeaks->setWordWrap(true);
  m_shakingPeaks->setTextInteractionFlags(Qt::TextSelectableByMouse);
  frame->addWidget(m_shakingPeaks);
  frame->addWidget(m_shaking, 1);
  frame->addWidget(m_shakingMoment, 1);
  pages->addTab(curves, tr("Torque and joint forces"));
  pages->addTab(shaking, tr("Shaking"));
  pages->addTab(polar, tr("Polar diagrams"));
  pages->addTab(m_machine, tr("Flywheel and motor"));
  connect(pages, &QTabWidget::currentChanged, this, &ForcePlotPanel::showMachinePage);
  layout->addWidget(m_charts, 1);

  // The two charts share the crank axis: same plot-area edges, so the cursors line up.
  for (ForceChartView* chart : {m_torque, m_joints, m_shaking, m_shakingMoment})
    connect(chart, &ForceChartView::resized, this, &ForcePlotPanel::alignCharts);
  connect(m_selector, &QComboBox::currentIndexChanged, this, [this] { refreshPolar(); });
  connect(forces, &ForceResults::changed, this, [this](bool cycle) {
    if (!cycle) return refreshCursor();
    refreshAll();
    m_machine->designChanged();
  });
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & Change::PlotAxis) refreshAll();
  });
  refreshAll();
}

void ForcePlotPanel::setAngleUnit(AngleUnit unit) {
  if (unit == m_unit) return;
  m_unit = unit;
  m_machine->setAngleUnit(unit);
  refreshAll();
}

void ForcePlotPanel::setPresentationScale(double factor) {
  m_legendsRefit = true;
  for (QChart* chart : {m_torque->chart(), m_joints->chart(), m_shaking->chart(), m_shakingMoment->chart(),
                        m_polar->chart(), m_machine->speedChart()->chart()})
    setChartScale(chart, factor);
  alignCharts();
}

void ForcePlotPanel::refreshColors() {
  for (QChart* chart : {m_torque->chart(), m_joints->chart(), m_shaking->chart(), m_shakingMoment->chart(),
                        m_polar->chart(), m_machine->speedChart()->chart()})
    applyChartColors(chart);
  m_machine->designChanged();
  refreshAll();
}

QString ForcePlotPanel::statusText() const { return m_status->text(); }

QString ForcePlotPanel::shakingPeakText() const { return m_shakingPeaks->text(); }

void ForcePlotPanel::showMachinePage() { m_machine->setOnScreen(m_onScreen && m_pages->currentWidget() == m_machine); }

void ForcePlotPanel::setOnScreen(bool onScreen) {
  if (onScreen == m_onScreen) return;
  m_onScreen = onScreen;
  showMachinePage();
  if (onScreen && m_stale) {
    m_stale = false;
    refreshAll();
  }
}

void ForcePlotPanel::refreshAll() {
  if (!m_onScreen) {
    m_stale = true;
    return;
  }
  const k::ForceSweep* cycle = m_forces->cycleForces();
  const k::SweepResult* sweep = m_forces->cycleSweep();
  QString status = m_forces->message();
  if (m_forces->state() == ForceResults::State::Disabled) status = tr("Forces are not being computed.");
  m_status->setText(status);
  m_status->setVisible(!status.isEmpty());
  m_charts->setVisible(cycle != nullptr && sweep != nullptr);
  if (cycle == nullptr || sweep == nullptr) return;

  const PlotXAxis x = plotXAxis(m_document->design(), *sweep, m_document->plotAxis(), m_unit);
  m_x = x;
  const k::ForceSweep* before = beforeForces();
  const DriveChart drive = driveChart(cycle->bodies);
  std::vector<ForceChartView::Curve> driveCurves;
  for (std::size_t i = 0; i < drive.curves.size(); ++i)
    driveCurves.push_back({QStringLiteral("drive_%1").arg(i), drive.curves[i], i == 0 ? linkColor(0) : linkColor(1)});
  const std::size_t driven = driveCurves.size();
  if (before != nullptr)
    for (std::size_t i = 0; i < driven; ++i)
      driveCurves.push_back({QStringLiteral("drive_%1_before").arg(i), tr("%1 before balancing").arg(drive.curves[i]),
                             driveCurves[i].color, Qt::DashLine});
  m_torque->setCurves(driveCurves);
  if (m_torque->chart()->title() != drive.title) m_torque->chart()->setTitle(drive.title);
  m_runs.resize(driveCurves.size());
  for (std::size_t i = 0; i < driven; ++i) buildDriveRuns(*sweep, *cycle, i, m_unit, m_runs[i], x.source);
  if (before != nullptr)
    for (std::size_t i = 0; i < driven; ++i) buildDriveRuns(*sweep, *before, i, m_unit, m_runs[driven + i], x.source);
  // Data that came before the last ones settled are a drag's, or an animation's.
  const DataFlow flow = m_settleTimer.isActive() ? DataFlow::Changing : DataFlow::Settled;
  bool relayout = m_torque->setData(m_runs, drive.valueTitle, x, flow);

  const std::vector<ForceJoint> joints = forceJoints(cycle->bodies);
  std::vector<ForceChartView::Curve> curves;
  for (const ForceJoint& j : joints)
    curves.push_back({QStringLiteral("joint_") + j.name, j.prismatic ? tr("%1 |N|").arg(j.name) : j.name, j.color});
  if (before != nullptr)
    for (std::size_t i = 0; i < joints.size(); ++i)
      curves.push_back({curves[i].key + QStringLiteral("_before"), tr("%1 before").arg(curves[i].name), curves[i].color,
                        Qt::DashLine});
  m_joints->setCurves(curves);
  m_runs.resize(curves.size());
  for (std::size_t i = 0; i < joints.size(); ++i) {
    buildJointForceRuns(*sweep, *cycle, joints[i], m_unit, m_runs[i], x.source);
    if (before != nullptr) buildJointForceRuns(*sweep, *before, joints[i], m_unit, m_runs[joints.size() + i], x.source);
  }
  relayout |= m_joints->setData(m_runs, tr("|F| [N]"), x, flow);
  refreshShaking(x, flow, relayout);

  if (joints != m_jointList || m_selector->count() == 0) {
    const QString kept = m_selector->currentText();
    const QSignalBlocker block(m_selector);
    m_selector->clear();
    for (const ForceJoint& j : joints)
      if (!j.prismatic) m_selector->addItem(tr("joint %1").arg(j.name));
    m_selector->addItem(tr("the shaking force"));
    m_selector->setCurrentIndex(std::max(0, m_selector->findText(kept)));
    m_jointList = joints;
  }
  refreshPolar();
  refreshCursor();
  if (relayout) alignCharts();  // tick labels and the legend may have changed width
  m_settleTimer.start();
}

void ForcePlotPanel::refreshShaking(const PlotXAxis& x, DataFlow flow, bool& relayout) {
  const k::ForceSweep& cycle = *m_forces->cycleForces();
  const k::SweepResult& sweep = *m_forces->cycleSweep();
  const k::ForceSweep* before = beforeForces();
  std::vector<ForceChartView::Curve> shaking{{QStringLiteral("shaking_x"), tr("Fx"), linkColor(0)},
                                             {QStringLiteral("shaking_y"), tr("Fy"), linkColor(1)},
                                             {QStringLiteral("shaking"), tr("|F|"), linkColor(2)}};
  if (before != nullptr)
    shaking.push_back({QStringLiteral("shaking_before"), tr("|F| before balancing"), linkColor(2), Qt::DashLine});
  m_shaking->setCurves(shaking);
  m_runs.resize(shaking.size());
  for (const auto& [i, curve] : {std::pair{0, ShakingCurve::X}, {1, ShakingCurve::Y}, {2, ShakingCurve::Magnitude}})
    buildShakingForceRuns(sweep, cycle, curve, m_unit, m_runs[static_cast<std::size_t>(i)], x.source);
  if (before != nullptr) buildShakingForceRuns(sweep, *before, ShakingCurve::Magnitude, m_unit, m_runs[3], x.source);
  relayout |= m_shaking->setData(m_runs, tr("force [N]"), x, flow);

  const k::Mechanism& m = m_document->design().mechanism;
  const auto pivot = cycle.bodies.momentPoint;
  const QString about = pivot && pivot->index < m.points.size()
                            ? tr("about %1").arg(QString::fromStdString(m.points[pivot->index].name))
                            : tr("about the origin");
  const QString title = tr("Shaking moment %1").arg(about);
  if (m_shakingMoment->chart()->title() != title) m_shakingMoment->chart()->setTitle(title);
  std::vector<ForceChartView::Curve> moment{{QStringLiteral("shaking_moment"), tr("M"), linkColor(3)}};
  if (before != nullptr)
    moment.push_back({QStringLiteral("shaking_moment_before"), tr("M before balancing"), linkColor(3), Qt::DashLine});
  m_shakingMoment->setCurves(moment);
  m_runs.resize(moment.size());
  buildShakingMomentRuns(sweep, cycle, m_unit, m_runs[0], x.source);
  if (before != nullptr) buildShakingMomentRuns(sweep, *before, m_unit, m_runs[1], x.source);
  relayout |= m_shakingMoment->setData(m_runs, tr("moment [N·m]"), x, flow);

  // The peaks refined between samples, as the core found them with the cycle (force_extrema.h).
  const k::ShakingPeaks* peaks = m_forces->shakingPeaks();
  m_shakingPeaks->setText(peaks != nullptr
                              ? tr("Peak shaking force %1 N at %2; peak shaking moment %3 N·m %4 at %5 (refined "
                                   "between the %6 samples).")
                                    .arg(numberText(peaks->force.value, 'g', 4),
                                         xReadoutText(extremumX(peaks->force, x.source, m_unit), x, m_unit),
                                         numberText(peaks->moment.value, 'g', 4), about,
                                         xReadoutText(extremumX(peaks->moment, x.source, m_unit), x, m_unit))
                                    .arg(cycle.size())
                              : tr("No sample of the cycle has its forces solved."));
  if (before != nullptr && peaks != nullptr) {
    const ShakingPeaks was = shakingPeaks(*before);
    m_shakingPeaks->setText(m_shakingPeaks->text() +
                            tr(" Before balancing (dashed, the best samples): %1 N and %2 N·m.")
                                .arg(numberText(was.force, 'g', 4), numberText(was.moment, 'g', 4)));
  }
}

void ForcePlotPanel::setBefore(const k::Design& after, const k::LinkageDynamics& before) {
  m_before = Before{after, before, std::nullopt};
  refreshAll();
}

const k::ForceSweep* ForcePlotPanel::beforeForces() {
  if (!m_before) return nullptr;
  // Only beside the design the balance made: any other design, an undo included, drops them.
  if (m_before->after != m_document->design()) {
    m_before.reset();
    return nullptr;
  }
  if (!m_before->forces) {
    auto forces = k::sweepForces(m_before->after.mechanism, m_before->dynamics, *m_forces->cycleSweep());
    if (!forces) {
      m_before.reset();
      return nullptr;
    }
    m_before->forces = std::move(*forces);
  }
  return &*m_before->forces;
}

bool ForcePlotPanel::shakingSelected() const { return m_selector->currentIndex() == m_selector->count() - 1; }

void ForcePlotPanel::settleValueRanges() {
  bool changed = m_torque->settleValueRange();
  changed |= m_joints->settleValueRange();
  changed |= m_shaking->settleValueRange();
  changed |= m_shakingMoment->settleValueRange();
  if (changed) alignCharts();
}

void ForcePlotPanel::alignCharts() {
  if (!m_charts->isVisible()) return;
  alignPlotAreas({m_torque->chart(), m_joints->chart()});
  alignPlotAreas({m_shaking->chart(), m_shakingMoment->chart()});
  // Only growing until the fonts change (see PlotPanel::fitLegends: the page's scroll bar).
  const bool afresh = std::exchange(m_legendsRefit, false);
  for (ForceChartView* chart : {m_torque, m_joints, m_shaking, m_shakingMoment})
    chart->setMinimumHeight(legendFittingHeight(chart, afresh ? kChartMinimumHeight : chart->minimumHeight()));
}

std::optional<double> ForcePlotPanel::cursorX() const { return ui::cursorX(*m_document, m_x, m_unit); }

void ForcePlotPanel::refreshCursor() {
  if (!m_onScreen) {
    m_stale = true;
    return;
  }
  const std::optional<double> x = m_forces->cycleForces() != nullptr ? cursorX() : std::nullopt;
  for (ForceChartView* chart : {m_torque, m_joints, m_shaking, m_shakingMoment}) chart->setCursorX(x);
  const k::PoseForces* pose = m_forces->poseForces();
  const int joint = m_selector->currentIndex();
  if (pose != nullptr && shakingSelected()) {
    m_polar->setCurrent(QPointF(pose->shakingForce.x(), pose->shakingForce.y()));
  } else if (pose != nullptr && joint >= 0 && static_cast<std::size_t>(joint) < pose->revolute.size()) {
    const Eigen::Vector2d& f = pose->revolute[static_cast<std::size_t>(joint)];
    m_polar->setCurrent(QPointF(f.x(), f.y()));
  } else {
    m_polar->setCurrent(std::nullopt);
  }
}

void ForcePlotPanel::refreshPolar() {
  const k::ForceSweep* cycle = m_forces->cycleForces();
  const int joint = m_selector->currentIndex();
  if (cycle == nullptr || joint < 0) return;
  if (shakingSelected()) {
    SeriesRuns locus;
    buildShakingPolarRuns(*cycle, locus);
    m_polar->setLocus(locus, tr("Shaking force on the frame"), linkColor(2));
    refreshCursor();
    return;
  }
  // Revolute joints come first in forceJoints, so the selector's index is the revolute index.
  const auto index = static_cast<std::size_t>(joint);
  SeriesRuns locus;
  buildPolarRuns(*cycle, index, locus);
  m_polar->setLocus(
      locus,
      tr("Joint %1: force on %2 from %3")
          .arg(QString::fromStdString(cycle->bodies.revolutes[index].name),
               QString::fromStdString(cycle->bodies.bodies[cycle->bodies.revolutes[index].body.index].name),
               QString::fromStdString(cycle->bodies.bodies[cycle->bodies.revolutes[index].hub.index].name)),
      m_jointList.empty() ? QColor(Qt::black) : m_jointList[index].color);
  refreshCursor();
}

}  // namespace linkwright::ui
