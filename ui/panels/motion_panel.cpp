#include "ui/panels/motion_panel.h"

#include "ui/number_text.h"
#include "ui/readout_label.h"

#include "ui/animation/crank_animator.h"
#include "ui/document/mechanism_document.h"
#include "ui/number_box.h"

#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

MotionPanel::MotionPanel(MechanismDocument* document, CrankAnimator* animator, QWidget* parent)
    : QWidget(parent), m_document(document), m_animator(animator), m_branch(new QComboBox(this)),
      m_play(new QPushButton(this)), m_back(new QPushButton(this)), m_forward(new QPushButton(this)),
      m_step(new NumberBox(this)), m_loop(new QCheckBox(tr("Loop"), this)),
      m_position(new QSlider(Qt::Horizontal, this)), m_positionText(new ReadoutLabel(this)),
      m_branchLabel(new QLabel(tr("&Branch"), this)) {
  // One row, as a media player's transport: it sits in the window's Motion bar, in sight
  // whatever the window's height (the side panel scrolls).
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 0, 4, 0);
  m_branch->addItem(tr("Open"));
  m_branch->addItem(tr("Crossed"));
  m_branch->setToolTip(tr("Assembly branch: open has sin(θ4 − θ3) > 0, crossed is its mirror image"));
  m_branchLabel->setBuddy(m_branch);
  layout->addWidget(m_branchLabel);
  layout->addWidget(m_branch);
  layout->addSpacing(8);
  m_back->setIcon(style()->standardIcon(QStyle::SP_MediaSeekBackward));
  m_back->setToolTip(tr("Step back"));
  m_forward->setIcon(style()->standardIcon(QStyle::SP_MediaSeekForward));
  m_forward->setToolTip(tr("Step forward"));
  m_play->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
  m_play->setToolTip(tr("Play / pause (Space)"));
  m_step->setRange(0.01, 180.0);
  m_step->setValue(k::radToDeg(animator->stepAngle()));
  m_step->setSuffix(tr("°"));
  m_step->setToolTip(tr("Step angle"));
  m_loop->setChecked(animator->isLooping());
  for (QWidget* w : std::initializer_list<QWidget*>{m_back, m_play, m_forward, m_step, m_loop}) layout->addWidget(w);
  m_position->setRange(-1800, 1800);  // tenths of a degree
  m_position->setMinimumWidth(120);
  layout->addWidget(m_position, 1);
  // Wide enough for the longest text ("t = 12.345 s · crank angle θ₂ = -179.9°"), so the row
  // does not move as the numbers change.
  m_positionText->setMinimumWidth(fontMetrics().horizontalAdvance(tr("t = 00.000 s · crank angle θ₂ = -000.0°")));
  layout->addWidget(m_positionText);

  connect(m_branch, &QComboBox::currentIndexChanged, this, [this] { editBranch(); });
  connect(m_play, &QPushButton::clicked, animator, &CrankAnimator::togglePlay);
  connect(m_back, &QPushButton::clicked, animator, &CrankAnimator::stepBackward);
  connect(m_forward, &QPushButton::clicked, animator, &CrankAnimator::stepForward);
  connect(m_step, &QDoubleSpinBox::valueChanged, this, &MotionPanel::onStep);
  connect(m_loop, &QCheckBox::toggled, animator, &CrankAnimator::setLooping);
  connect(m_position, &QSlider::valueChanged, this, &MotionPanel::onSlider);
  connect(animator, &CrankAnimator::playingChanged, this, [this](bool playing) {
    m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
  });
  connect(document, &MechanismDocument::changed, this, [this](Changes what) {
    if (what & Change::Design) refreshDesign();
    refreshMotion();
  });
  refreshDesign();
  refreshMotion();
}

QString MotionPanel::positionText() const { return m_positionText->text(); }

void MotionPanel::refreshDesign() {
  const k::Design& design = m_document->design();
  const Scale scale = m_document->onTimeBase()                                 ? Scale::Time
                      : k::inputKind(design.mechanism) == k::InputKind::Length ? Scale::LinearInput
                                                                               : Scale::CrankAngle;
  const double span = scale == Scale::Time          ? design.time->toTime - design.time->fromTime
                      : scale == Scale::LinearInput ? design.toDeg - design.fromDeg
                                                    : 0.0;
  // A new time span or linear grid starts with a tenth of it as the step.
  const bool spanChanged = span != m_span;
  if (span > 0.0 && spanChanged) {
    if (scale == Scale::Time) m_animator->setStepTime(span / 10.0);
    else m_animator->setStepAngle(span / 10.0);
  }
  m_span = span;
  if (scale != m_scale || (scale != Scale::CrankAngle && spanChanged)) {
    m_scale = scale;
    const QSignalBlocker blockStep(m_step);
    const QSignalBlocker blockSlider(m_position);
    const QString unit = QString::fromStdString(design.mechanism.lengthUnit);
    switch (scale) {
    case Scale::Time:
      m_step->setRange(0.001, 1e6);
      m_step->setDecimals(3);
      m_step->setSuffix(tr(" s"));
      m_step->setValue(m_animator->stepTime());
      m_step->setToolTip(tr("Step time"));
      m_position->setRange(0, kTimeSliderSteps);
      break;
    case Scale::LinearInput:
      m_step->setRange(std::max(span, 1e-12) / 1000.0, std::max(span, 1e-12));
      m_step->setDecimals(4);
      m_step->setSuffix(QStringLiteral(" ") + unit);
      m_step->setValue(m_animator->stepAngle());
      m_step->setToolTip(tr("Step of the input"));
      m_position->setRange(0, kTimeSliderSteps);
      break;
    case Scale::CrankAngle:
      m_step->setRange(0.01, 180.0);
      m_step->setDecimals(2);
      m_step->setSuffix(tr("°"));
      m_step->setValue(k::radToDeg(m_animator->stepAngle()));
      m_step->setToolTip(tr("Step angle"));
      m_position->setRange(-1800, 1800);
      break;
    }
  }
  // Other linkages choose a branch per joint, in the dimensions panel.
  const auto& fourBar = m_document->fourBar();
  m_branchLabel->setVisible(fourBar.has_value());
  m_branch->setVisible(fourBar.has_value());
  if (!fourBar) return;
  const QSignalBlocker block(m_branch);
  m_branch->setCurrentIndex(fourBar->branch == k::Branch::Open ? 0 : 1);
}

void MotionPanel::refreshMotion() {
  const QSignalBlocker block(m_position);
  const k::Design& design = m_document->design();
  const k::Mechanism& m = design.mechanism;
  const double q = m_document->crankAngle();
  // The input in its own words: "crank angle θ₂ = 45.0°", "tip path position = 0.15 m".
  const QString input = k::inputKind(m) == k::InputKind::Angle
                            ? tr("crank angle θ₂ = %1°").arg(numberText(k::radToDeg(q), 'f', 1))
                            : tr("%1 = %2 %3")
                                  .arg(QString::fromStdString(k::inputName(m)), numberText(q, 'g', 5),
                                       QString::fromStdString(m.lengthUnit));
  switch (m_scale) {
  case Scale::Time: {
    const k::TimeBase& time = *design.time;
    const double span = time.toTime - time.fromTime;
    const double u = span > 0.0 ? (m_document->time() - time.fromTime) / span : 0.0;
    m_position->setValue(static_cast<int>(std::lround(u * kTimeSliderSteps)));
    m_positionText->setText(tr("t = %1 s · %2").arg(numberText(m_document->time(), 'f', 3), input));
    return;
  }
  case Scale::LinearInput: {
    const double u = m_span > 0.0 ? (q - design.fromDeg) / m_span : 0.0;
    m_position->setValue(static_cast<int>(std::lround(std::clamp(u, 0.0, 1.0) * kTimeSliderSteps)));
    m_positionText->setText(input.left(1).toUpper() + input.mid(1));
    return;
  }
  case Scale::CrankAngle: break;
  }
  const double deg = k::radToDeg(std::remainder(q, 2.0 * k::kPi));
  m_position->setValue(static_cast<int>(std::lround(deg * 10.0)));
  m_positionText->setText(tr("Crank angle θ₂ = %1°").arg(numberText(deg, 'f', 1)));
}

void MotionPanel::onSlider(int value) {
  const k::Design& design = m_document->design();
  const double u = static_cast<double>(value) / kTimeSliderSteps;
  switch (m_scale) {
  case Scale::CrankAngle: m_document->setCrankAngle(k::degToRad(value / 10.0)); return;
  case Scale::LinearInput: m_document->setCrankAngle(design.fromDeg + m_span * u); return;
  case Scale::Time:
    m_document->setTime(design.time->fromTime + (design.time->toTime - design.time->fromTime) * u);
    return;
  }
}

void MotionPanel::onStep(double value) {
  switch (m_scale) {
  case Scale::Time: m_animator->setStepTime(value); return;
  case Scale::LinearInput: m_animator->setStepAngle(value); return;
  case Scale::CrankAngle: m_animator->setStepAngle(k::degToRad(value)); return;
  }
}

void MotionPanel::editBranch() {
  const auto& fourBar = m_document->fourBar();
  if (!fourBar) return;
  k::Design d = m_document->design();
  d.mechanism =
      k::withFourBarBranch(d.mechanism, *fourBar, m_branch->currentIndex() == 0 ? k::Branch::Open : k::Branch::Crossed);
  if (m_document->edit(d, tr("Switch assembly branch"))) refreshDesign();
}

}  // namespace linkwright::ui
