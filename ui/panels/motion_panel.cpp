#include "ui/panels/motion_panel.h"

#include "ui/number_text.h"

#include "ui/animation/crank_animator.h"
#include "ui/document/edit_design_command.h"
#include "ui/document/mechanism_document.h"
#include "ui/settings.h"

#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/units.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QVBoxLayout>

#include <cmath>

namespace linkwright::ui {

namespace k = kinematics;

MotionPanel::MotionPanel(MechanismDocument* document, CrankAnimator* animator, Settings* settings, QWidget* parent)
    : QWidget(parent), m_document(document), m_animator(animator), m_settings(settings),
      m_speed(new QDoubleSpinBox(this)), m_speedUnit(new QComboBox(this)), m_alpha(new QDoubleSpinBox(this)),
      m_branch(new QComboBox(this)), m_play(new QPushButton(this)), m_back(new QPushButton(this)),
      m_forward(new QPushButton(this)), m_step(new QDoubleSpinBox(this)), m_loop(new QCheckBox(tr("Loop"), this)),
      m_angle(new QSlider(Qt::Horizontal, this)), m_angleText(new QLabel(this)) {
  auto* layout = new QVBoxLayout(this);
  auto* drive = new QGroupBox(tr("Drive"), this);
  auto* form = new QFormLayout(drive);
  m_driveForm = form;
  auto* speedRow = new QHBoxLayout;
  m_speed->setRange(-1e5, 1e5);
  m_speed->setDecimals(4);
  m_speed->setKeyboardTracking(false);
  m_speedUnit->addItems({tr("rpm"), tr("rad/s")});
  m_speedUnit->setCurrentIndex(settings->speedInRpm() ? 0 : 1);
  speedRow->addWidget(m_speed, 1);
  speedRow->addWidget(m_speedUnit);
  form->addRow(tr("Crank speed ω₂"), speedRow);
  m_alpha->setRange(-1e6, 1e6);
  m_alpha->setDecimals(4);
  m_alpha->setSuffix(tr(" rad/s²"));
  m_alpha->setKeyboardTracking(false);
  form->addRow(tr("Crank accel. α₂"), m_alpha);
  m_branch->addItem(tr("Open"));
  m_branch->addItem(tr("Crossed"));
  m_branch->setToolTip(tr("Assembly branch: open has sin(θ4 − θ3) > 0, crossed is its mirror image"));
  form->addRow(tr("Branch"), m_branch);
  layout->addWidget(drive);

  auto* motion = new QGroupBox(tr("Motion"), this);
  auto* motionLayout = new QVBoxLayout(motion);
  auto* buttons = new QHBoxLayout;
  m_back->setIcon(style()->standardIcon(QStyle::SP_MediaSeekBackward));
  m_back->setToolTip(tr("Step back"));
  m_forward->setIcon(style()->standardIcon(QStyle::SP_MediaSeekForward));
  m_forward->setToolTip(tr("Step forward"));
  m_play->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
  m_play->setToolTip(tr("Play / pause (Space)"));
  m_step->setRange(0.01, 180.0);
  m_step->setValue(30.0);
  m_step->setSuffix(tr("°"));
  m_step->setToolTip(tr("Step angle"));
  m_loop->setChecked(true);
  buttons->addWidget(m_back);
  buttons->addWidget(m_play);
  buttons->addWidget(m_forward);
  buttons->addWidget(m_step);
  buttons->addWidget(m_loop);
  motionLayout->addLayout(buttons);
  m_angle->setRange(-1800, 1800);  // tenths of a degree
  motionLayout->addWidget(m_angle);
  motionLayout->addWidget(m_angleText);
  layout->addWidget(motion);

  connect(m_speed, &QDoubleSpinBox::valueChanged, this, [this] { editSpeed(); });
  connect(m_speedUnit, &QComboBox::currentIndexChanged, this, [this](int index) {
    m_settings->setSpeedInRpm(index == 0);
    refreshDesign();
  });
  connect(m_alpha, &QDoubleSpinBox::valueChanged, this, [this] { editAlpha(); });
  connect(m_branch, &QComboBox::currentIndexChanged, this, [this] { editBranch(); });
  connect(m_play, &QPushButton::clicked, animator, &CrankAnimator::togglePlay);
  connect(m_back, &QPushButton::clicked, animator, &CrankAnimator::stepBackward);
  connect(m_forward, &QPushButton::clicked, animator, &CrankAnimator::stepForward);
  connect(m_step, &QDoubleSpinBox::valueChanged, this,
          [this](double deg) { m_animator->setStepAngle(k::degToRad(deg)); });
  connect(m_loop, &QCheckBox::toggled, animator, &CrankAnimator::setLooping);
  connect(m_angle, &QSlider::valueChanged, this,
          [this](int tenths) { m_document->setCrankAngle(k::degToRad(tenths / 10.0)); });
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

void MotionPanel::refreshDesign() {
  const k::Design& d = m_document->design();
  const bool rpm = m_speedUnit->currentIndex() == 0;
  {
    const QSignalBlocker block(m_speed);
    m_speed->setSuffix(rpm ? tr(" rpm") : tr(" rad/s"));
    m_speed->setValue(rpm ? k::radPerSecToRpm(d.omega) : d.omega);
  }
  {
    const QSignalBlocker block(m_alpha);
    m_alpha->setValue(d.alpha);
  }
  // Other linkages choose a branch per joint, in the dimensions panel.
  const auto& fourBar = m_document->fourBar();
  m_driveForm->setRowVisible(m_branch, fourBar.has_value());
  if (!fourBar) return;
  const QSignalBlocker block(m_branch);
  m_branch->setCurrentIndex(fourBar->branch == k::Branch::Open ? 0 : 1);
}

void MotionPanel::refreshMotion() {
  const double deg = k::radToDeg(std::remainder(m_document->crankAngle(), 2.0 * k::kPi));
  {
    const QSignalBlocker block(m_angle);
    m_angle->setValue(static_cast<int>(std::lround(deg * 10.0)));
  }
  m_angleText->setText(tr("Crank angle θ₂ = %1°").arg(numberText(deg, 'f', 1)));
}

void MotionPanel::editSpeed() {
  const bool rpm = m_speedUnit->currentIndex() == 0;
  const double omega = rpm ? k::rpmToRadPerSec(m_speed->value()) : m_speed->value();
  k::Design d = m_document->design();
  d.omega = omega;
  if (m_document->edit(d, tr("Change crank speed"), MergeKey{ContinuousEdit::Speed, 0, m_editSerial++}))
    refreshDesign();
}

void MotionPanel::editAlpha() {
  const double alpha = m_alpha->value();
  k::Design d = m_document->design();
  d.alpha = alpha;
  if (m_document->edit(d, tr("Change crank acceleration"), MergeKey{ContinuousEdit::Acceleration, 0, m_editSerial++}))
    refreshDesign();
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
