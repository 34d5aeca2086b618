#include "ui/export/animation_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSpinBox>

#include <algorithm>

namespace linkwright::ui {

namespace {

QSpinBox* intBox(int low, int high, int value, const QString& suffix, QWidget* parent) {
  auto* box = new QSpinBox(parent);
  box->setRange(low, high);
  box->setValue(value);
  box->setSuffix(suffix);
  return box;
}

}  // namespace

AnimationDialog::AnimationDialog(const QSize& canvasSize, const QString& cycle, QWidget* parent) : QDialog(parent) {
  using S = AnimationSettings;
  const S defaults;
  m_frames = intBox(S::kMinFrames, S::kMaxFrames, defaults.frames, {}, this);
  m_delay = intBox(S::kMinDelayMs, S::kMaxDelayMs, defaults.frameDelayMs, tr(" ms"), this);
  m_delay->setSingleStep(10);  // GIF counts delays in 1/100 s
  m_width = intBox(S::kMinSide, S::kMaxSide, std::clamp(canvasSize.width(), S::kMinSide, S::kMaxSide), tr(" px"), this);
  m_height =
      intBox(S::kMinSide, S::kMaxSide, std::clamp(canvasSize.height(), S::kMinSide, S::kMaxSide), tr(" px"), this);
  m_loop = new QCheckBox(tr("&Loop forever"), this);
  m_loop->setChecked(defaults.loopForever);
  m_duration = new QLabel(this);

  setWindowTitle(tr("Export animation"));
  auto* form = new QFormLayout(this);
  auto* intro = new QLabel(tr("An animated GIF of the canvas over %1, as the canvas shows it (paths, arrows, "
                              "centres), for slides and web pages.")
                               .arg(cycle),
                           this);
  intro->setWordWrap(true);
  form->addRow(intro);
  form->addRow(tr("&Frames per cycle"), m_frames);
  form->addRow(tr("Frame &delay"), m_delay);
  form->addRow(QString(), m_duration);
  auto* size = new QHBoxLayout;
  size->addWidget(m_width);
  size->addWidget(new QLabel(QStringLiteral("×"), this));
  size->addWidget(m_height);
  form->addRow(tr("Image size"), size);
  form->addRow(QString(), m_loop);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(m_frames, &QSpinBox::valueChanged, this, &AnimationDialog::updateDuration);
  connect(m_delay, &QSpinBox::valueChanged, this, &AnimationDialog::updateDuration);
  updateDuration();
}

void AnimationDialog::updateDuration() {
  const int delayCs = (m_delay->value() + 5) / 10;
  m_duration->setText(tr("%1 frames per second; one cycle lasts %2 s")
                          .arg(100.0 / delayCs, 0, 'g', 3)
                          .arg(m_frames->value() * delayCs / 100.0, 0, 'g', 4));
}

AnimationSettings AnimationDialog::settings() const {
  AnimationSettings s;
  s.frames = m_frames->value();
  s.frameDelayMs = m_delay->value();
  s.size = QSize(m_width->value(), m_height->value());
  s.loopForever = m_loop->isChecked();
  return s;
}

}  // namespace linkwright::ui
