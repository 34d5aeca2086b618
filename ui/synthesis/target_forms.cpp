#include "ui/synthesis/target_forms.h"

#include "ui/synthesis/target_table.h"

#include "kinematics/model/units.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QVBoxLayout>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

constexpr int kTimingColumn = 2;

QFormLayout* formUnder(QVBoxLayout* layout) {
  auto* form = new QFormLayout;
  form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  layout->addLayout(form);
  return form;
}

// Three poses a four-bar carries a part through (Norton-style: the part moves right and turns).
const std::vector<std::vector<double>> kDefaultPoses{{0.0, 0.0, 0.0}, {40.0, 20.0, 25.0}, {75.0, 15.0, 55.0}};

// Six points on the coupler curve of the thesis crank-rocker (frame 60, crank 25, coupler 70,
// rocker 45 mm; coupler point 35 along, 20 across), every 60° of crank from 0°: a path a
// four-bar is known to trace. Rounded to 0.1 mm.
const std::vector<std::vector<double>> kDefaultPath{{59.8, 49.0, 0.0},  {37.9, 57.6, 60.0},  {10.7, 46.4, 120.0},
                                                    {2.7, 25.0, 180.0}, {26.1, 16.2, 240.0}, {51.4, 27.0, 300.0}};

}  // namespace

MotionForm::MotionForm(QWidget* parent)
    : ClosedForm(parent), m_poses(new TargetTable({tr("x"), tr("y"), tr("angle (°)")}, tr("Pose"), 2, 3, this)),
      m_fullTurn(new QCheckBox(tr("A motor turns the crank round"), this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(new QLabel(tr("Coupler poses: the coupler point and the coupler's angle (two or three)"), this));
  m_poses->setToolTip(tr("Pick on canvas: press at the point, drag along the coupler's direction, release"));
  layout->addWidget(m_poses);
  QFormLayout* form = formUnder(layout);
  // Circle points that make a compact four-bar without defects for the default poses (frame
  // 69.6, crank 34.8, coupler 44.7, rocker 48 mm; μ ≥ 43.8° over the motion).
  m_ax = addNumber(form, tr("Circle point A x"), 20.0, Kind::Length, "circlePoints.a.x");
  m_ay = addNumber(form, tr("Circle point A y"), 20.0, Kind::Length, "circlePoints.a.y");
  m_bx = addNumber(form, tr("Circle point B x"), 60.0, Kind::Length, "circlePoints.b.x");
  m_by = addNumber(form, tr("Circle point B y"), 40.0, Kind::Length, "circlePoints.b.y");
  nameField("circlePoints.a", tr("Circle point A"));
  nameField("circlePoints.b", tr("Circle point B"));
  m_centreA = addNumber(form, tr("Centre A on its bisector"), 30.0, Kind::Length, "centreA");
  m_centreB = addNumber(form, tr("Centre B on its bisector"), -15.0, Kind::Length, "centreB");
  for (QDoubleSpinBox* box : {m_centreA, m_centreB})
    box->setToolTip(
        tr("Two poses only: where the ground pivot lies on the perpendicular bisector of the circle "
           "point's two positions (signed, positive to the left)"));
  form->addRow(m_fullTurn);
  for (int i = 0; i < 3; ++i) nameField("poses[" + std::to_string(i) + "]", tr("Pose %1").arg(i + 1));
  nameField("poses", tr("Poses"));
  m_poses->setRows(kDefaultPoses);
  updateCentres();
  connect(m_poses, &TargetTable::edited, this, [this] {
    updateCentres();
    emit edited();
  });
  connect(m_fullTurn, &QCheckBox::toggled, this, &ProblemForm::edited);
}

void MotionForm::updateCentres() {
  const bool two = m_poses->rowCount() == 2;
  m_centreA->setEnabled(two);
  m_centreB->setEnabled(two);
}

k::Result<ClosedFormRequest> MotionForm::request() const {
  const auto rows = m_poses->values();
  if (!rows) return rows.error();
  MotionRequest r;
  for (const std::vector<double>& row : *rows) r.poses.push_back({{row[0], row[1]}, k::degToRad(row[2])});
  r.circlePoints = {{m_ax->value(), m_ay->value()}, {m_bx->value(), m_by->value()}};
  r.centreA = m_centreA->value();
  r.centreB = m_centreB->value();
  r.options.needsFullRotation = m_fullTurn->isChecked();
  r.options.lengthUnit = lengthUnit().toStdString();
  return ClosedFormRequest(r);
}

void MotionForm::load(const k::SynthesisTargets& t) {
  const k::MotionTargets& m = t.motion;
  if (m.poses.size() >= 2) {
    std::vector<std::vector<double>> rows;
    for (const k::CouplerPose& p : m.poses) rows.push_back({p.point.x(), p.point.y(), k::radToDeg(p.angle)});
    const QSignalBlocker block(m_poses);
    m_poses->setRows(rows);
  }
  const std::pair<QDoubleSpinBox*, double> numbers[] = {{m_ax, m.circlePoints.a.x()}, {m_ay, m.circlePoints.a.y()},
                                                        {m_bx, m.circlePoints.b.x()}, {m_by, m.circlePoints.b.y()},
                                                        {m_centreA, m.centreA},       {m_centreB, m.centreB}};
  for (const auto& [box, value] : numbers) {
    const QSignalBlocker block(box);
    box->setValue(value);
  }
  const QSignalBlocker block(m_fullTurn);
  m_fullTurn->setChecked(m.needsFullRotation);
  updateCentres();
}

void MotionForm::store(k::SynthesisTargets& t) const {
  k::MotionTargets& m = t.motion;
  if (const auto rows = m_poses->values()) {
    m.poses.clear();
    for (const std::vector<double>& row : *rows) m.poses.push_back({{row[0], row[1]}, k::degToRad(row[2])});
  }
  m.circlePoints = {{m_ax->value(), m_ay->value()}, {m_bx->value(), m_by->value()}};
  m.centreA = m_centreA->value();
  m.centreB = m_centreB->value();
  m.needsFullRotation = m_fullTurn->isChecked();
}

bool MotionForm::appendPose(const Eigen::Vector2d& point, double angle) {
  return m_poses->appendRow({point.x(), point.y(), k::radToDeg(angle)});
}

PathForm::PathForm(QWidget* parent)
    : ProblemForm(parent),
      m_points(new TargetTable({tr("x"), tr("y"), tr("crank angle (°)")}, tr("Point"), 4, 10, this)),
      m_timing(new QCheckBox(tr("Prescribed crank angles (timing)"), this)), m_reference(new QComboBox(this)),
      m_starts(new QSpinBox(this)), m_fullTurn(new QCheckBox(tr("A motor turns the crank round"), this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(new QLabel(tr("Points the coupler point must pass through, in order (4 to 10)"), this));
  layout->addWidget(m_points);
  QFormLayout* form = formUnder(layout);
  form->addRow(m_timing);
  m_reference->addItems({tr("from the first target's"), tr("from the frame line")});
  form->addRow(tr("Crank angles measured"), m_reference);
  m_starts->setRange(1, 100000);
  m_starts->setValue(k::kDefaultPathStarts);
  m_starts->setToolTip(tr("Local searches from random starts: more find better linkages and take longer"));
  form->addRow(tr("Starts"), m_starts);
  form->addRow(m_fullTurn);
  nameField("points", tr("Targets"));
  nameField("timing", tr("Crank angles"));
  nameField("starts", tr("Starts"));
  m_points->setRows(kDefaultPath);
  const auto showTiming = [this](bool on) {
    m_points->table()->setColumnHidden(kTimingColumn, !on);
    m_reference->setEnabled(on);
  };
  showTiming(false);
  connect(m_timing, &QCheckBox::toggled, this, [this, showTiming](bool on) {
    showTiming(on);
    emit edited();
  });
  connect(m_points, &TargetTable::edited, this, &ProblemForm::edited);
  connect(m_reference, &QComboBox::currentIndexChanged, this, &ProblemForm::edited);
  connect(m_starts, &QSpinBox::valueChanged, this, &ProblemForm::edited);
  connect(m_fullTurn, &QCheckBox::toggled, this, &ProblemForm::edited);
}

k::Result<PathRequest> PathForm::request() const {
  const bool timing = m_timing->isChecked();
  const auto rows = m_points->values(timing ? -1 : kTimingColumn);
  if (!rows) return rows.error();
  PathRequest r;
  for (const std::vector<double>& row : *rows) {
    r.target.points.push_back({row[0], row[1]});
    if (timing) r.target.timing.push_back(k::degToRad(row[kTimingColumn]));
  }
  r.target.timingReference = m_reference->currentIndex() == 0 ? k::TimingReference::Start : k::TimingReference::Frame;
  r.target.needsFullRotation = m_fullTurn->isChecked();
  r.target.lengthUnit = lengthUnit().toStdString();
  r.options.starts = m_starts->value();
  return r;
}

void PathForm::load(const k::SynthesisTargets& t) {
  const k::PathTarget& p = t.path;
  const bool timing = !p.timing.empty() && p.timing.size() == p.points.size();
  if (p.points.size() >= 4) {
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < p.points.size(); ++i)
      rows.push_back({p.points[i].x(), p.points[i].y(), timing ? k::radToDeg(p.timing[i]) : 0.0});
    const QSignalBlocker block(m_points);
    m_points->setRows(rows);
  }
  {
    const QSignalBlocker block(m_timing);
    m_timing->setChecked(timing);
  }
  m_points->table()->setColumnHidden(kTimingColumn, !timing);
  m_reference->setEnabled(timing);
  for (QWidget* w : std::initializer_list<QWidget*>{m_reference, m_starts, m_fullTurn}) w->blockSignals(true);
  m_reference->setCurrentIndex(p.timingReference == k::TimingReference::Frame ? 1 : 0);
  m_starts->setValue(t.pathSearch.starts);
  m_fullTurn->setChecked(p.needsFullRotation);
  for (QWidget* w : std::initializer_list<QWidget*>{m_reference, m_starts, m_fullTurn}) w->blockSignals(false);
}

void PathForm::store(k::SynthesisTargets& t) const {
  const bool timing = m_timing->isChecked();
  if (const auto rows = m_points->values(timing ? -1 : kTimingColumn)) {
    t.path.points.clear();
    t.path.timing.clear();
    for (const std::vector<double>& row : *rows) {
      t.path.points.push_back({row[0], row[1]});
      if (timing) t.path.timing.push_back(k::degToRad(row[kTimingColumn]));
    }
  }
  t.path.timingReference = m_reference->currentIndex() == 0 ? k::TimingReference::Start : k::TimingReference::Frame;
  t.path.needsFullRotation = m_fullTurn->isChecked();
  t.path.lengthUnit = lengthUnit().toStdString();
  t.pathSearch.starts = m_starts->value();
}

bool PathForm::appendPoint(const Eigen::Vector2d& point) {
  // A picked point's crank angle continues the last row's spacing guess: 60° on.
  double angle = 0.0;
  const int last = m_points->rowCount() - 1;
  if (const QTableWidgetItem* item = last >= 0 ? m_points->table()->item(last, kTimingColumn) : nullptr)
    angle = item->text().toDouble() + 60.0;
  return m_points->appendRow({point.x(), point.y(), angle});
}

}  // namespace linkwright::ui
